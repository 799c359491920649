// checker colours without `checker`, and a checker cell size of zero
// expect: HSC1007 HSC0303
BRDFs   {
    diffuse = (1, 1, 1), checker_diffuse = (0, 0, 1);
    diffuse = (1, 1, 1), checker = 0;
}
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Sphere (0, 0, 0.3), 0.05, #1; Sphere (0.1, 0, 0.3), 0.05, #2; }
