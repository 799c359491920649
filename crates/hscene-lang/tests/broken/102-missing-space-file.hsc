// A space file that is missing.
// expect: HSC0505
Globals { space = "no-such-space.json"; }
