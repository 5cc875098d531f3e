reflectedLight.directDiffuse *= probeVolumeDirectScale;
reflectedLight.directSpecular *= probeVolumeDirectScale;
