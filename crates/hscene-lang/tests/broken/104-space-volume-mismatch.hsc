// A space file whose "volume" is not its domain's (2.0298832128...).
// expect: HSC1014
Globals { space = "spaces/m004-wrong-volume.json"; }
