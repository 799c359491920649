// Thesis Fig. 27 (net 0): h-polyhedra with the Wythoff symbols 2|3 4 and
// 5/2 — the cuboctahedron (left) and the small stellated dodecahedron
// {5/2, 5} (right) — and the three golden rectangles of an icosahedron
// (middle).
//
// Hyperbolic property: these figures are defined by incidence and symmetry
// (vertices of a Euclidean figure centred at the origin are vertices of the
// hyperbolic one), but the metric differs. The "golden rectangles" are no
// longer rectangles: the four h-segments joining the icosahedron's vertices
// in each of the planes x = 0, y = 0, z = 0 meet at acute angles, because
// an h-quadrilateral has an angle sum below 360°. Here the icosahedron's
// circumradius is 0.7, so every corner is about 78.4°.
//
// Every figure's centre is at hyperbolic distance 1.6 from the eye, on rays
// 32° apart.
Globals {
    resolution = (400, 220);
    window_size = (0.2, 0.11);    // Euclidean, on the plane z = 0.1: 90° wide
    net_type = 0;
    to = (0, 0, 0.1);
    background = (0.03, 0.03, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    gold:  ambient = (0.3, 0.22, 0.08), diffuse = (0.85, 0.65, 0.25),
           specular = (1, 1, 1), shininess = 40;
    star:  ambient = (0.25, 0.1, 0.25), diffuse = (0.75, 0.35, 0.8),
           specular = (1, 1, 1), shininess = 40;
    green: ambient = (0.1, 0.25, 0.15), diffuse = (0.35, 0.8, 0.5),
           specular = (0.6, 0.6, 0.6), shininess = 30;
    edge:  ambient = (0.5, 0.5, 0.5), diffuse = (0.9, 0.9, 0.9);
}

Points {
    left = (-0.351886, 0, 0.563135);    // distance 1.6, 32° left
    middle = (0, 0, 0.664037);          // tanh(0.8): distance 1.6
    right = (0.351886, 0, 0.563135);    // distance 1.6, 32° right
    o = (0, 0, 0);
    xaxis = (0.5, 0, 0);
    yaxis = (0, 0.5, 0);
    lamp = (-0.1, 0.35, 0.3);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9): the figures are
// about 1.2 from the lamp and 1.6 from the eye, hence the intensities.
Lights {
    %lamp, (25, 25, 25), (20, 20, 20);
    (0, 0, 0), (20, 20, 20), (5, 5, 5);
}

Objects {
    Cuboctahedron 0.45, #gold, edges = 0.012, edge_material = #edge, at = %left;
    SmallStellatedDodecahedron 0.5, #star, at = %right;
    golden: GoldenRectangles 0.7, #green, edges = 0.012, edge_material = #edge;
}

Transformations {
    // Turn the golden rectangles (built at the origin) so that none of them
    // is seen edge-on, then move them out to %middle.
    x: hline (%o, %xaxis);
    y: hline (%o, %yaxis);
    out: hline (%o, %middle);
    @golden->Rotate(%y, 0.6);
    @golden->Rotate(%x, 0.45);
    @golden->Translate(%out);
}
