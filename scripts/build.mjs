#!/usr/bin/env node
// Builds the package into dist/ (or `--out <folder>`), emptied first so nothing stale ships:
// 1. the GLSL embedded into src/shaders.generated.ts (scripts/shaders.mjs);
// 2. the library's ES modules and declarations (tsconfig.build.json) → dist/;
// 3. the CLI (cli/tsconfig.build.json) → dist/cli/: only the cli/ files are written, and their
//    imports of ../src/… are pointed at the library's modules of step 2, so each module ships once
//    (a plain `tsc -p cli/tsconfig.build.json` would emit a second copy of them under dist/src/);
// 4. the bake page bundled by Vite (cli/bakePage/vite.config.ts) → dist/cli/page/, so an
//    installed `capture-lighting` serves plain files and needs no Vite.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';

const root = fileURLToPath( new URL( '..', import.meta.url ) );
const outArgument = process.argv.indexOf( '--out' );
const out = outArgument >= 0 ? resolve( process.argv[ outArgument + 1 ] ?? '' ) : resolve( root, 'dist' );
const srcFolder = resolve( root, 'src' ) + sep;
const cliFolder = resolve( root, 'cli' ) + sep;

function fail( message ) {

	console.error( `build: ${message}` );
	process.exit( 1 );

}

/** Compiles a tsconfig with `overrides`; `keep( file )` says which emitted files to write. */
function compile( configPath, overrides, keep, transformers ) {

	const config = ts.getParsedCommandLineOfConfigFile( configPath, overrides, { ...ts.sys, onUnRecoverableConfigFileDiagnostic: ( d ) => fail( ts.flattenDiagnosticMessageText( d.messageText, '\n' ) ) } );
	const program = ts.createProgram( config.fileNames, config.options );
	const written = [];
	const writeFile = ( file, text ) => {

		if ( ! keep( resolve( file ) ) ) return;
		mkdirSync( dirname( file ), { recursive: true } );
		writeFileSync( file, text );
		written.push( file );

	};

	const result = program.emit( undefined, writeFile, undefined, false, transformers );
	const diagnostics = [ ...config.errors, ...ts.getPreEmitDiagnostics( program ), ...result.diagnostics ];
	if ( diagnostics.length > 0 ) {

		const host = { getCanonicalFileName: ( f ) => f, getCurrentDirectory: () => root, getNewLine: () => '\n' };
		fail( `${relative( root, configPath )}:\n${ts.formatDiagnosticsWithColorAndContext( diagnostics, host )}` );

	}

	return written;

}

/**
 * Rewrites the CLI's relative imports that reach into src/ so that, from the file's place under
 * `<out>/cli/`, they name the library's emitted module (`../src/io/index.js` → `../io/index.js`).
 * The target must exist (the library is built first); any other import leaving cli/ is an error,
 * as nothing else ships.
 */
function pointAtLibrary( context ) {

	return ( sourceFile ) => {

		const source = resolve( sourceFile.fileName );
		if ( ! source.startsWith( cliFolder ) ) return sourceFile; // src/ is emitted by the library build
		const emitted = resolve( out, relative( root, source ) );
		const rewrite = ( specifier ) => {

			if ( ! specifier.startsWith( '.' ) ) return specifier;
			const target = resolve( dirname( source ), specifier );
			if ( target.startsWith( cliFolder ) ) return specifier;
			if ( ! target.startsWith( srcFolder ) ) fail( `${relative( root, source )} imports ${specifier}, which is outside cli/ and src/ and would not ship.` );
			const library = resolve( out, target.slice( srcFolder.length ) );
			if ( ! existsSync( library ) ) fail( `${relative( root, source )} imports ${specifier}, but the library build has no ${relative( root, library )}.` );
			const path = relative( dirname( emitted ), library ).split( sep ).join( '/' );
			return path.startsWith( '.' ) ? path : './' + path;

		};

		// Only a changed specifier gets a new node: the others keep the emitter's original text.
		const visit = ( node ) => {

			const f = context.factory;
			const declaration = ts.isImportDeclaration( node ) || ts.isExportDeclaration( node );
			if ( declaration && node.moduleSpecifier && ts.isStringLiteral( node.moduleSpecifier ) ) {

				const text = rewrite( node.moduleSpecifier.text );
				if ( text === node.moduleSpecifier.text ) return node;
				const specifier = f.createStringLiteral( text, true );
				return ts.isImportDeclaration( node )
					? f.updateImportDeclaration( node, node.modifiers, node.importClause, specifier, node.attributes )
					: f.updateExportDeclaration( node, node.modifiers, node.isTypeOnly, node.exportClause, specifier, node.attributes );

			}

			const dynamic = ts.isCallExpression( node ) && node.expression.kind === ts.SyntaxKind.ImportKeyword;
			const argument = dynamic ? node.arguments[ 0 ] : undefined;
			if ( argument && ts.isStringLiteral( argument ) && rewrite( argument.text ) !== argument.text ) {

				const specifier = f.createStringLiteral( rewrite( argument.text ), true );
				return f.updateCallExpression( node, node.expression, node.typeArguments, [ specifier ] );

			}

			return ts.visitEachChild( node, visit, context );

		};

		return ts.visitNode( sourceFile, visit );

	};

}

rmSync( out, { recursive: true, force: true } );

const shaders = spawnSync( process.execPath, [ resolve( root, 'scripts/shaders.mjs' ) ], { stdio: 'inherit' } );
if ( shaders.status !== 0 ) fail( 'scripts/shaders.mjs failed.' );

const library = compile( resolve( root, 'tsconfig.build.json' ), { outDir: out }, () => true );

// rootDir is the repository (cli/ imports ../src/), so cli/main.ts is emitted to <out>/cli/main.js.
const cliOut = resolve( out, 'cli' ) + sep;
const cli = compile( resolve( root, 'cli/tsconfig.build.json' ), { outDir: out }, ( file ) => file.startsWith( cliOut ), { after: [ pointAtLibrary ] } );

const { build } = await import( 'vite' );
await build( { configFile: resolve( root, 'cli/bakePage/vite.config.ts' ), logLevel: 'warn', build: { outDir: resolve( out, 'cli/page' ) } } );

console.log( `build: ${library.length} library files, ${cli.length} CLI modules and the bake page → ${relative( root, out ) || '.'}/` );
