/**
 * Node 20 gaps for three's glTF exporter and loader, stubbed and nothing else: GLTFExporter writes
 * through the browser's FileReader (absent: a minimal one over Blob.arrayBuffer() stands in), and three's FileLoader,
 * which GLTFLoader uses for a .gltf's data: URI buffers, creates ProgressEvents (absent: without
 * one the load never finishes). The scene has no textures (those need a canvas in Node).
 */
export function installGLTFNodeStubs(): void {

	if ( typeof ( globalThis as { ProgressEvent?: unknown } ).ProgressEvent === 'undefined' ) {

		( globalThis as { ProgressEvent?: unknown } ).ProgressEvent = class extends Event {

			readonly lengthComputable: boolean; readonly loaded: number; readonly total: number;
			constructor( type: string, init: { lengthComputable?: boolean; loaded?: number; total?: number } = {} ) {

				super( type );
				this.lengthComputable = init.lengthComputable ?? false;
				this.loaded = init.loaded ?? 0;
				this.total = init.total ?? 0;

			}

		};

	}

	if ( typeof ( globalThis as { FileReader?: unknown } ).FileReader !== 'undefined' ) return;
	class NodeFileReader {

		result: ArrayBuffer | string | null = null;
		onloadend: ( () => void ) | null = null;
		readAsArrayBuffer( blob: Blob ): void {

			void blob.arrayBuffer().then( ( buffer ) => {

				this.result = buffer;
				this.onloadend?.();

			} );

		}

		readAsDataURL( blob: Blob ): void {

			void blob.arrayBuffer().then( ( buffer ) => {

				this.result = `data:${blob.type || 'application/octet-stream'};base64,${Buffer.from( buffer ).toString( 'base64' )}`;
				this.onloadend?.();

			} );

		}

	}

	( globalThis as { FileReader?: unknown } ).FileReader = NodeFileReader;

}
