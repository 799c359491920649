// uniform honeycomb mistakes: a node beyond 3, a node ringed twice, rings that are not numbers, depth and colours with a uniform honeycomb, colours with the dual ringed (node 3 alone), parity with five cells round an edge, an unknown colouring rule
// expect: HSC0403 HSC0403 HSC0108 HSC0112 HSC0112 HSC0112 HSC0403
BRDFs   { edge: diffuse = (0.9, 0.8, 0.5); glass: diffuse = (0.2, 0.4, 0.9), trans = 0.6; }
Lights  { (0, 0, 0), (1, 1, 1), (1, 1, 1); }
Objects {
    Honeycomb {4,3,5}, #edge, rings = (0, 4);
    Honeycomb {5,3,4}, #edge, rings = (1, 1);
    Honeycomb {5,3,5}, #edge, rings = #glass;
    Honeycomb {3,5,3}, #edge, depth = 2, colors = (#edge, #glass), rings = (0, 1);
    Honeycomb {4,3,5}, #edge, colors = (#edge, #glass), rings = (3);
    Honeycomb {4,3,5}, #edge, colors = (#edge, #glass), color_by = parity;
    Honeycomb {5,3,4}, #edge, colors = (#edge, #glass), color_by = shells;
}
