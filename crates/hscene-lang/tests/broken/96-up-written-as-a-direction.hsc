// the eye off the origin and `up` written as the direction +y: from this eye the up point rolls the picture
// expect: HSC1012
Globals { from = (0.5, 0.5, 0); to = (0, 0, 0.6); up = (0, 0.3, 0); }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { (0, 0.3, 0.3), (1, 1, 1), (1, 1, 1); }
Objects { Sphere (0, 0, 0.6), 0.1, #1; }
