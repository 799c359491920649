// Thesis Fig. 37 (net 4): a Lambert quadrilateral and a regular h-cube,
// each moved step by step away from the centre of the view h-plane by
// h-translations along one h-line of that plane. Lambert quadrilaterals
// (sides 0.8 and 0.7) have their right-angled corner on the line, at
// distances 0, 0.9, 1.8 and 2.7 from the centre (to the right); cubes
// (circumradius 0.25) are centred on the line at 0.6, 1.5, 2.4 and 3.3
// (to the left).
//
// Hyperbolic property: a translation is an isometry, so all four copies are
// congruent; but the screen shows the view h-plane as a Poincaré disk
// (net 4, like net 2), whose scale shrinks towards the rim as
// (1 - |x|^2) / 2. The copies get smaller in the Euclidean sense, their
// edges (h-lines: arcs orthogonal to the rim) curve more, and the rods of
// the edges, all of one hyperbolic thickness, get thinner with the rest.
// The cubes, which stick out of the plane towards the eye, are also seen
// ever more from the side: the eye looks at them at a grazing angle, and
// the central projection onto the view plane stretches them along the line
// (the thesis's "thicker edges").
Globals {
    resolution = (400, 180);
    window_size = (2, 0.9);        // Euclidean, in the great disk: its full width
    net_type = 4;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.5, 0.5, 0.5);
    recursion_depth = 0;
}

BRDFs {
    face: ambient = (0.5, 0.18, 0.12), diffuse = (0.9, 0.35, 0.25),
          specular = (0.3, 0.3, 0.3), shininess = 20;
    box:  ambient = (0.25, 0.35, 0.6), diffuse = (0.4, 0.55, 0.95),
          specular = (0.3, 0.3, 0.3), shininess = 20;
    edge: ambient = (0.9, 0.9, 0.85), diffuse = (0.9, 0.9, 0.85);
}

Points {
    o = (0, 0, 0);
    centre = (0, 0, 0.761594);     // tanh(1): the view h-plane at distance 2
    // On the x axis of the plane z = 0, at the distances given above.
    l1 = (0.421899, 0, 0); l2 = (0.716298, 0, 0); l3 = (0.874053, 0, 0);
    c0 = (-0.291313, 0, 0); c1 = (-0.635149, 0, 0);
    c2 = (-0.833655, 0, 0); c3 = (-0.928858, 0, 0);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9): the far copies
// are more than 3 from the lamp and get almost nothing from it, hence the
// strong ambient term.
Lights {
    (0, 0.1, 0.3), (8, 8, 8), (4, 4, 4);
}

Objects {
    L0: Lambert 0.8, 0.7, #face, edges = 0.025, edge_material = #edge;
    L1: Lambert 0.8, 0.7, #face, edges = 0.025, edge_material = #edge, at = %l1;
    L2: Lambert 0.8, 0.7, #face, edges = 0.025, edge_material = #edge, at = %l2;
    L3: Lambert 0.8, 0.7, #face, edges = 0.025, edge_material = #edge, at = %l3;
    C0: Cube 0.25, #box, edges = 0.015, edge_material = #edge, at = %c0;
    C1: Cube 0.25, #box, edges = 0.015, edge_material = #edge, at = %c1;
    C2: Cube 0.25, #box, edges = 0.015, edge_material = #edge, at = %c2;
    C3: Cube 0.25, #box, edges = 0.015, edge_material = #edge, at = %c3;
}

Transformations {
    // Everything was placed in the plane z = 0 (translations along the x
    // axis keep it); move that plane forward onto the view h-plane.
    forward: hline (%o, %centre);
    @L0->Translate(%forward); @L1->Translate(%forward);
    @L2->Translate(%forward); @L3->Translate(%forward);
    @C0->Translate(%forward); @C1->Translate(%forward);
    @C2->Translate(%forward); @C3->Translate(%forward);
}
