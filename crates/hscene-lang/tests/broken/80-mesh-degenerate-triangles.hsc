// lint: one face of the mesh repeats a vertex, so it has no area
// expect: HSC1009
BRDFs   { clay: ambient = (0.2, 0.15, 0.1), diffuse = (0.8, 0.6, 0.45); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Mesh "meshes/degenerate.obj", 0.3, #clay, at = (0, 0, 0.45); }
