// a focus distance with no aperture: the camera is a pinhole, so it does nothing
// expect: HSC1007
Globals { focus = 2; }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Sphere (0, 0, 0.4), 0.1, #1; }
