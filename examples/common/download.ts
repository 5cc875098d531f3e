/** Offers `data` to the user as a downloaded file named `name`. */
export function download( name: string, data: BlobPart, type: string ): void {

	const link = document.createElement( 'a' );
	link.href = URL.createObjectURL( new Blob( [ data ], { type } ) );
	link.download = name;
	link.click();
	URL.revokeObjectURL( link.href );

}

/** A layout or volume name as a file name: runs of non-word characters become '-'. */
export function fileName( name: string, extension: string ): string {

	return `${name.replace( /\W+/g, '-' )}.${extension}`;

}
