// Thesis Fig. 38, middle panel (net 4): an ideal h-pentagon — all five vertices
// on the absolute — lying in the view h-plane, one vertex turned to the
// right (on the plane's x axis). The files fig38-net3/4/2.hsc differ only
// in net_type and window_size.
//
// Hyperbolic property: an angle whose vertex is an ideal point measures 0,
// so an ideal polygon has angle sum 0; its sides meet only at infinity and
// its area is nevertheless finite, 3π. Each side is a whole h-line, drawn
// here as an h-cylinder (points at distance 0.03 from the line), which
// thins out to nothing at the absolute.
//
// Net 4 shows the great disk like net 2, each pixel interpolated from the
// net-3 nodes around it; this removes net 3's uneven sampling, and the
// picture matches net 2 up to interpolation quality.
Globals {
    resolution = (300, 300);
    window_size = (2, 2);          // Euclidean, in the great disk: the whole view h-plane
    net_type = 4;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.5, 0.5, 0.5);
    recursion_depth = 0;
}

BRDFs {
    face: ambient = (0.35, 0.45, 0.8), diffuse = (0.4, 0.5, 0.9),
          specular = (0.3, 0.3, 0.3), shininess = 20;
    edge: ambient = (0.9, 0.85, 0.7), diffuse = (0.9, 0.85, 0.7);
}

Points {
    o = (0, 0, 0);
    centre = (0, 0, 0.462117);     // tanh(0.5): the view h-plane at distance 1
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9); the pentagon
// reaches out to infinity, so most of it lives on the ambient term.
Lights {
    (0, 0.1, 0.1), (5, 5, 5), (2, 2, 2);
}

Objects {
    pentagon: IdealPentagon #face, edges = 0.03, edge_material = #edge;
}

Transformations {
    // Turn the pentagon (built in the plane z = 0 with a vertex at the top)
    // a quarter turn so that a vertex lies on the x axis, then move its
    // plane forward onto the view h-plane.
    forward: hline (%o, %centre);
    @pentagon->Rotate(%forward, -1.5707963267948966);
    @pentagon->Translate(%forward);
}
