// Thesis Fig. 26 (net 3): the five Platonic h-polyhedra as planar models
// (top row), wireframes (middle) and combined (bottom): tetrahedron, cube,
// octahedron, dodecahedron, icosahedron from left to right.
//
// Hyperbolic property: the regular polyhedra of absolute geometry are the
// same five as in Euclidean space (the vertices of a Euclidean regular solid
// centred at the origin are those of a regular h-polyhedron), but their
// faces are h-polygons lying on spheres orthogonal to the absolute and their
// dihedral angles are smaller than the Euclidean ones.
//
// The fifteen solids (circumradius 0.17) sit at the nodes of net 3 itself:
// the view h-plane is at distance 1.1 from the eye, and the centres lie in
// it at equidistant coordinates a = -0.9, -0.45, 0, 0.45, 0.9 (distance from
// the vertical h-line) and b = 0.45, 0, -0.45 (distance from the horizontal
// one); coordinates from the net-3 formula x1 = sinh a, x2 = sinh b on the
// plane's hyperboloid, moved by the translation T_f of SPEC 3.2. So in the
// image the columns and rows are evenly spaced, even though the outer
// columns are farther from the eye: net 3 samples hyperbolic length evenly.
Globals {
    resolution = (400, 280);
    window_size = (2.6, 1.82);   // hyperbolic lengths on the view h-plane
    net_type = 3;
    to = (0, 0, 0.50052021119);  // tanh(1.1 / 2)
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    face: ambient = (0.15, 0.2, 0.35), diffuse = (0.3, 0.5, 0.9),
          specular = (0.8, 0.8, 0.8), shininess = 40;
    wire: ambient = (0.3, 0.3, 0.25), diffuse = (0.9, 0.85, 0.7),
          specular = (1, 1, 1), shininess = 60;
}

Points {
    t1 = (-0.292119, 0.132424, 0.572698); t2 = (-0.155248, 0.155248, 0.533435); t3 = (0.000000, 0.163834, 0.518666);
    t4 = (0.155248, 0.155248, 0.533435); t5 = (0.292119, 0.132424, 0.572698);
    m1 = (-0.302706, 0.000000, 0.564442); m2 = (-0.163834, 0.000000, 0.518666); m3 = (0.000000, 0.000000, 0.500520);
    m4 = (0.163834, 0.000000, 0.518666); m5 = (0.302706, 0.000000, 0.564442);
    b1 = (-0.292119, -0.132424, 0.572698); b2 = (-0.155248, -0.155248, 0.533435); b3 = (0.000000, -0.163834, 0.518666);
    b4 = (0.155248, -0.155248, 0.533435); b5 = (0.292119, -0.132424, 0.572698);
    lamp = (-0.1, 0.25, 0.1);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9): at distance ~1 it
// needs an intensity near 10 to light the solids fully.
Lights {
    %lamp, (10, 10, 10), (8, 8, 8);
    (0, 0, 0), (4, 4, 4), (2, 2, 2);
}

Objects {
    Tetrahedron 0.17, #face, at = %t1;
    Cube 0.17, #face, at = %t2;
    Octahedron 0.17, #face, at = %t3;
    Dodecahedron 0.17, #face, at = %t4;
    Icosahedron 0.17, #face, at = %t5;

    Tetrahedron 0.17, #wire, wireframe = 0.008, at = %m1;
    Cube 0.17, #wire, wireframe = 0.008, at = %m2;
    Octahedron 0.17, #wire, wireframe = 0.008, at = %m3;
    Dodecahedron 0.17, #wire, wireframe = 0.008, at = %m4;
    Icosahedron 0.17, #wire, wireframe = 0.008, at = %m5;

    Tetrahedron 0.17, #face, edges = 0.008, edge_material = #wire, at = %b1;
    Cube 0.17, #face, edges = 0.008, edge_material = #wire, at = %b2;
    Octahedron 0.17, #face, edges = 0.008, edge_material = #wire, at = %b3;
    Dodecahedron 0.17, #face, edges = 0.008, edge_material = #wire, at = %b4;
    Icosahedron 0.17, #face, edges = 0.008, edge_material = #wire, at = %b5;
}
