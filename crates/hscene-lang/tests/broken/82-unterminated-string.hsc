// a file name whose closing quote is missing
// expect: HSC0001
BRDFs   { clay: ambient = (0.2, 0.15, 0.1), diffuse = (0.8, 0.6, 0.45); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects {
    Mesh "meshes/degenerate.obj, 0.3, #clay;
    Sphere (0, 0, 0.3), 0.05, #clay;
}
