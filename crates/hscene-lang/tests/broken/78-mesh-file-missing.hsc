// the mesh file does not exist (a typo in its name)
// expect: HSC0501
BRDFs   { clay: ambient = (0.2, 0.15, 0.1), diffuse = (0.8, 0.6, 0.45); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Mesh "meshes/bunnny.ply", 0.5, #clay, at = (0, 0, 0.45); }
