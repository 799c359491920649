// the cubic honeycomb {4,3,4} tiles flat space, not hyperbolic space
// expect: HSC0313
BRDFs   { edge: diffuse = (0.9, 0.8, 0.5); }
Lights  { (0, 0, 0), (1, 1, 1), (1, 1, 1); }
Objects { Honeycomb {4,3,4}, #edge, edges = 0.02; }
