// net 2 with the target a hair from the eye: every direction crowds into the middle of the picture
// expect: HSC1011
Globals { net_type = 2; to = (0, 0, 0.005); window_size = (1.6, 1.6); }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { (0, 0.3, 0), (1, 1, 1), (1, 1, 1); }
Objects { Sphere (0, 0, 0.3), 0.05, #1; }
