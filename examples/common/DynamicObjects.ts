import * as THREE from 'three';
import { loadCharacter, type Character } from './character.js';
import { screenBox } from './screenBox.js';
import type { Viewer } from './Viewer.js';

/** The walk of a page's character. */
export interface WalkOptions {

	/** The character's walk, a closed loop. */
	path: THREE.Curve<THREE.Vector3>;
	/** Character height in scene units. */
	height: number;
	/** Seconds per loop of the path. Default 30. */
	loopSeconds?: number;
	/** Where a white test ball stands when the page has no `ball=x,y,z` (default: no ball). */
	ball?: number[];

}

/**
 * What moves in a scene page and is lit by the probes one object at a time: the character walking
 * its loop (the Fox, or a stand-in), the extra spheres of `spheres=N` following it, and the white
 * test ball (`ball=x,y,z`, or the page's), which stays put. None of them appears in the captures.
 */
export class DynamicObjects {

	/** The character, the spheres and the ball: what a page adds to its volume. */
	readonly list: THREE.Object3D[] = [];
	/** The walking character (null with `character=0`). */
	readonly character: Character | null;
	/** The character's height in scene units (the spheres, the ball and the probe markers scale with it). */
	readonly height: number;
	private readonly spheres: THREE.Mesh[] = [];
	private readonly ball: THREE.Mesh | null = null;
	private readonly path: THREE.Curve<THREE.Vector3>;
	private readonly loopSeconds: number;
	private readonly frozen: boolean;

	/** Loads the character (unless `character=0`) and adds it, the spheres and the ball to the scene. */
	static async load( viewer: Viewer, walk: WalkOptions ): Promise<DynamicObjects> {

		const url = `${viewer.assets}fox/Fox.glb`;
		const character = viewer.query.character ? await loadCharacter( url, walk.height ) : null;
		if ( character ) {

			viewer.report.character = character.kind;
			if ( character.kind === 'fallback' ) {

				viewer.overlay.notice( `Character asset not found at ${url} — showing a stand-in. ${character.reason}` );

			}

			viewer.scene.add( character.object );

		}

		return new DynamicObjects( viewer, walk, character );

	}

	private constructor( viewer: Viewer, { path, height, loopSeconds = 30, ball: pageBall }: WalkOptions, character: Character | null ) {

		this.path = path;
		this.height = height;
		this.loopSeconds = loopSeconds;
		this.frozen = viewer.query.time !== null;
		this.character = character;
		const count = viewer.query.spheres;
		for ( let i = 0; i < count; i ++ ) {

			const material = new THREE.MeshStandardMaterial( { color: new THREE.Color().setHSL( i / count, 0.3, 0.7 ), roughness: 0.6 } );
			const sphere = new THREE.Mesh( new THREE.SphereGeometry( height * 0.25, 16, 8 ), material );
			sphere.userData.phase = i / count;
			this.spheres.push( sphere );
			viewer.scene.add( sphere );

		}

		const at = viewer.query.ball ?? pageBall;
		if ( at ) {

			// A white, rough test ball that stays put: it shows the probe light at one point.
			const material = new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } );
			const ball = new THREE.Mesh( new THREE.SphereGeometry( height * 0.5, 48, 24 ), material );
			ball.position.fromArray( at );
			ball.name = 'test ball';
			this.ball = ball;
			viewer.scene.add( ball );

		}

		this.list.push( ...( character ? [ character.object ] : [] ), ...this.spheres, ...( this.ball ? [ this.ball ] : [] ) );

	}

	/** Poses everything at `time` seconds; `delta` advances the walk animation (a frozen time poses it). */
	move( time: number, delta: number ): void {

		const path = this.path;
		const u = ( ( time / this.loopSeconds ) % 1 + 1 ) % 1;
		if ( this.character ) {

			const object = this.character.object;
			path.getPointAt( u, object.position );
			const ahead = path.getPointAt( ( u + 0.001 ) % 1 );
			object.lookAt( ahead.x, object.position.y, ahead.z );
			// A frozen time (?t=) poses the character deterministically, for screenshots.
			if ( this.frozen ) this.character.mixer?.setTime( time );
			else this.character.mixer?.update( delta );

		}

		const h = this.height;
		for ( const sphere of this.spheres ) {

			const phase = sphere.userData.phase as number;
			path.getPointAt( ( u + phase ) % 1, sphere.position );
			sphere.position.y += h * ( 0.8 + 0.5 * Math.sin( time * 2 + phase * 40 ) );
			sphere.position.x += h * Math.sin( phase * 97 );

		}

	}

	/** Where the character's cell is looked up: half its height above its feet. */
	characterCentre( target: THREE.Vector3 ): THREE.Vector3 {

		target.copy( this.character?.object.position ?? target.set( 0, 0, 0 ) );
		target.y += this.height * 0.5;
		return target;

	}

	/** The character's box on screen in CSS pixels: [ left, top, right, bottom ] (for tests). */
	characterScreenBox( camera: THREE.Camera, canvas: HTMLCanvasElement ): number[] {

		return screenBox( this.character?.object ?? new THREE.Object3D(), camera, canvas );

	}

	/** The test ball's box on screen in CSS pixels: [ left, top, right, bottom ] (for tests). */
	ballScreenBox( camera: THREE.Camera, canvas: HTMLCanvasElement ): number[] {

		return screenBox( this.ball ?? new THREE.Object3D(), camera, canvas );

	}

}
