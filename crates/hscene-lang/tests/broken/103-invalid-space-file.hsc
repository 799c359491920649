// A space file that is not one: a mesh is not JSON.
// expect: HSC0506
Globals { space = "meshes/degenerate.obj"; }
