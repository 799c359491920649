// the mesh file name is given as a point reference instead of a quoted name
// expect: HSC0108
Points  { bunny = (0, 0, 0.4); }
BRDFs   { clay: ambient = (0.2, 0.15, 0.1), diffuse = (0.8, 0.6, 0.45); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Mesh %bunny, 0.5, #clay; }
