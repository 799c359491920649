// several honeycomb mistakes: edges given twice, a negative vertex radius, a depth too deep, a depth past the base cell of horosphere-inscribed cells, colours that are not materials, an entry that is not whole, balls on ideal vertices, an option it does not take
// expect: HSC0112 HSC0303 HSC0403 HSC0108 HSC1007 HSC0103
BRDFs   { edge: diffuse = (0.9, 0.8, 0.5); glass: diffuse = (0.2, 0.4, 0.9), trans = 0.6; }
Lights  { (0, 0, 0), (1, 1, 1), (1, 1, 1); }
Objects {
    Honeycomb {5,3,4}, #edge, wireframe = 0.02, edges = 0.03;
    Honeycomb {5,3,5}, #edge, vertices = -0.1;
    Honeycomb {3,5,3}, #edge, depth = 9;
    Honeycomb {6,3,3}, #edge, depth = 1;
    Honeycomb {4,3,5}, #edge, colors = #glass;
    Honeycomb {4.5,3,5}, #edge;
    Honeycomb {3,3,6}, #edge, faces = #glass, vertices = 0.05;
    Honeycomb {4,4,4}, #edge, edge_material = #glass;
}
