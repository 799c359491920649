// Thesis Fig. 25, conformal companion (net 2): the same wireframe regular
// h-pentagon and Lambert quadrilateral as fig25-pentagon-lambert.hsc, in the
// same h-plane, now seen through net 2.
//
// Hyperbolic property: the Poincaré model is conformal, and net 2 shows the
// view h-plane (the plane the figures lie in) as a Poincaré disk. So here
// the angles are the true hyperbolic ones: all five corners of the pentagon
// are right angles (circumradius arcosh(cot 36°) ≈ 0.8314; a Euclidean
// pentagon has 108°), and the Lambert quadrilateral (sides 0.8 and 0.7 from
// its right-angled corner, which sits at the centre of the disk) has three
// right angles and a fourth of arccos(sinh 0.8 · sinh 0.7) ≈ 47.6°. Its two
// sides through the centre are diameters and look straight; the other two
// are arcs of circles orthogonal to the disk's rim.
Globals {
    resolution = (400, 300);
    window_size = (1.5, 1.125);    // Euclidean, in the great disk of the view plane
    net_type = 2;
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
