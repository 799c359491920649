// the PLY file is cut short: it promises three vertices and gives two
// expect: HSC0502
BRDFs   { clay: ambient = (0.2, 0.15, 0.1), diffuse = (0.8, 0.6, 0.45); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Mesh "meshes/truncated.ply", 0.5, #clay, at = (0, 0, 0.45); }
