// area-light options: `samples` on a point light, a misspelt option, a negative radius
// expect: HSC1007 HSC0103 HSC0403
BRDFs   { diffuse = (1, 1, 1); }
Lights  {
    (0, 0.5, 0), (1, 1, 1), (1, 1, 1), samples = 8;
    (0.3, 0.5, 0), (1, 1, 1), (1, 1, 1), raduis = 0.1;
    (-0.3, 0.5, 0), (1, 1, 1), (1, 1, 1), radius = -0.1;
}
Objects { Sphere (0, 0, 0.3), 0.05, #1; }
