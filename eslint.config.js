// Code style: three.js's mdcs style (eslint-config-mdcs), expressed with @stylistic's rules so it
// runs on TypeScript with ESLint's flat config, plus a line-length limit.
import stylistic from '@stylistic/eslint-plugin';
import tseslint from 'typescript-eslint';

const mdcs = {
	'@stylistic/array-bracket-spacing': [ 'error', 'always' ],
	'@stylistic/block-spacing': [ 'error', 'always' ],
	'@stylistic/brace-style': [ 'error', '1tbs', { allowSingleLine: true } ],
	'@stylistic/comma-spacing': [ 'error', { before: false, after: true } ],
	'@stylistic/comma-style': [ 'error', 'last' ],
	'@stylistic/computed-property-spacing': [ 'error', 'always' ],
	'@stylistic/eol-last': [ 'error', 'always' ],
	'@stylistic/function-call-spacing': [ 'error', 'never' ],
	'@stylistic/indent': [ 'error', 'tab', { SwitchCase: 1 } ],
	'@stylistic/key-spacing': [ 'error', { beforeColon: false } ],
	'@stylistic/new-parens': 'error',
	'@stylistic/no-trailing-spaces': [ 'error', { skipBlankLines: false } ],
	'@stylistic/no-whitespace-before-property': 'error',
	'@stylistic/object-curly-spacing': [ 'error', 'always' ],
	'@stylistic/padded-blocks': [ 'error', { blocks: 'always', switches: 'always', classes: 'always' }, { allowSingleLineBlocks: true } ],
	'@stylistic/semi': [ 'error', 'always' ],
	'@stylistic/semi-spacing': [ 'error', { before: false, after: true } ],
	'@stylistic/space-before-blocks': [ 'error', { functions: 'always', keywords: 'always', classes: 'always' } ],
	'@stylistic/space-before-function-paren': [ 'error', { anonymous: 'always', named: 'never', asyncArrow: 'ignore' } ],
	'@stylistic/space-in-parens': [ 'error', 'always' ],
	'@stylistic/space-infix-ops': 'error',
	// space-unary-ops is left out: it reads TypeScript's non-null assertion (x!) as a unary operator.
	'@stylistic/keyword-spacing': [ 'error', { before: true, after: true } ],
	'@stylistic/padding-line-between-statements': [ 'error', { blankLine: 'always', prev: 'multiline-block-like', next: '*' } ],
	'@stylistic/no-multi-spaces': 'error',
	'@stylistic/no-extra-semi': 'error',
};

export default [
	{ ignores: [ 'dist/**', 'node_modules/**', 'src/shaders.generated.ts', 'test/output/**', 'bench/results/**', 'bench/build/**', 'experiment/results/**' ] },
	{
		files: [ '**/*.ts', '**/*.js', '**/*.mjs' ],
		languageOptions: { parser: tseslint.parser, ecmaVersion: 2022, sourceType: 'module' },
		plugins: { '@stylistic': stylistic },
		rules: {
			...mdcs,
			'@stylistic/max-len': [ 'error', { code: 140, tabWidth: 4, ignoreUrls: true, ignoreRegExpLiterals: true, ignoreStrings: true, ignoreTemplateLiterals: true } ],
		},
	},
];
