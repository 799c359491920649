// {3,3,5} is the 600-cell, a tiling of the 3-sphere; {4,3} has two entries
// expect: HSC0313
BRDFs   { edge: diffuse = (0.9, 0.8, 0.5); }
Lights  { (0, 0, 0), (1, 1, 1), (1, 1, 1); }
Objects {
    Honeycomb {3,3,5}, #edge;
    Honeycomb {4,3}, #edge;
}
