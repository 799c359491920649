// Thesis Fig. 25 (net 0): a wireframe regular h-pentagon and a Lambert
// quadrilateral, lying in one h-plane that faces the eye.
//
// Hyperbolic property: polygons have smaller angles than their Euclidean
// counterparts. The pentagon has circumradius arcosh(cot 36°) ≈ 0.8314,
// which makes all five of its angles exactly 90° (it is the tile of the
// {5,4} tiling of the hyperbolic plane), not 108°. The Lambert quadrilateral
// (sides 0.8 and 0.7 from its right-angled corner) has three right angles;
// its fourth angle is arccos(sinh 0.8 · sinh 0.7) ≈ 47.6°.
//
// Net 0 is the pinhole camera. Seen from the eye every h-line looks straight
// (it lies in a Euclidean plane through the eye), and a plane orthogonal to
// the line of sight appears as its Klein (projective) model: edges straight,
// angles NOT true. The Lambert quadrilateral, whose right-angled corner sits
// at the foot of the line of sight, looks exactly like a Euclidean rectangle.
// The conformal view of the same plane is fig25-pentagon-lambert-disk.hsc.
Globals {
    resolution = (400, 300);
    window_size = (0.84, 0.63);    // Euclidean, on the plane z = tanh(1/2)
    net_type = 0;
    to = %centre;
    background = (0.03, 0.03, 0.06);
    ambient = (0.25, 0.25, 0.25);
    recursion_depth = 0;
}

BRDFs {
    wire: ambient = (0.6, 0.6, 0.55), diffuse = (0.9, 0.9, 0.8),
          specular = (0.6, 0.6, 0.6), shininess = 30;
    face: ambient = (0.45, 0.15, 0.1), diffuse = (0.9, 0.35, 0.25),
          specular = (0.4, 0.4, 0.4), shininess = 20;
}

Points {
    o = (0, 0, 0);
    centre = (0, 0, 0.46211715726000974);    // tanh(1/2): hyperbolic distance 1
    right = (0.39645538195, -0.14429795824, 0);  // distance 0.9 from o, 20° below +x
    lamp = (0, 0.15, 0.1);
}

// Light falls off as 1 / (4 pi sinh^2 r): at distance ~1 an intensity of
// about 12 gives full brightness.
Lights {
    %lamp, (10, 10, 10), (6, 6, 6);
}

Objects {
    pentagon: Pentagon 0.8314, #wire, wireframe = 0.02, at = %right;
    lambert:  Lambert 0.8, 0.7, #face, edges = 0.02, edge_material = #wire;
}

Transformations {
    // Both figures start in the plane z = 0 (the pentagon was moved along a
    // line of that plane, which keeps it). Turn the Lambert quadrilateral a
    // quarter turn (its sides now run up and to the left of its right-angled
    // corner), then move the whole plane forward by distance 1.
    forward: hline (%o, %centre);
    @lambert->Rotate(%forward, 1.5707963267948966);
    @pentagon->Translate(%forward);
    @lambert->Translate(%forward);
}
