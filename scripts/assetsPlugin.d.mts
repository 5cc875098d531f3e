import type { Plugin } from 'vite';

/** The asset folder: $CAPTURE_LIGHTING_ASSETS, else ../shared/assets beside the repository. */
export const assetsFolder: string;

/** Serves the asset folder at /assets/ on a Vite dev server. */
export function assetsPlugin(): Plugin;
