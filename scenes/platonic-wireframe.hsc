// The five Platonic h-polyhedra planar (top row), as wireframes (middle) and
// combined (bottom), after thesis Fig. 26. Every solid has hyperbolic
// circumradius 0.14 and stands at hyperbolic distance 1.1 from the eye.
Globals {
    resolution = (900, 560);
    window_size = (0.2, 0.124);
    to = (0, 0, 0.1);
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 1;
}

BRDFs {
    face: ambient = (0.15, 0.2, 0.35), diffuse = (0.3, 0.5, 0.9),
          specular = (0.8, 0.8, 0.8), shininess = 40;
    wire: ambient = (0.3, 0.3, 0.25), diffuse = (0.9, 0.85, 0.7),
          specular = (1, 1, 1), shininess = 60;
}

Points {
    // Columns at 32 and 16 degrees left and right of the view axis; rows at
    // 18 degrees up, level and 18 degrees down; all at Euclidean radius
    // tanh(1.1/2) = 0.5005.
    t1 = (-0.25571, 0.13296, 0.40921); t2 = (-0.13169, 0.14922, 0.45925);
    t3 = (0.00000, 0.15467, 0.47602);  t4 = (0.13169, 0.14922, 0.45925);
    t5 = (0.25571, 0.13296, 0.40921);
    m1 = (-0.26524, 0.00000, 0.42447); m2 = (-0.13796, 0.00000, 0.48113);
    m3 = (0.00000, 0.00000, 0.50052);  m4 = (0.13796, 0.00000, 0.48113);
    m5 = (0.26524, 0.00000, 0.42447);
    b1 = (-0.25571, -0.13296, 0.40921); b2 = (-0.13169, -0.14922, 0.45925);
    b3 = (0.00000, -0.15467, 0.47602);  b4 = (0.13169, -0.14922, 0.45925);
    b5 = (0.25571, -0.13296, 0.40921);
    lamp = (-0.1, 0.25, 0.1);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9): at distance ~1 it
// needs an intensity near 10 to light the solids fully.
Lights {
    %lamp, (8, 8, 8), (8, 8, 8);
    (0, 0, 0), (3, 3, 3), (2, 2, 2);
}

Objects {
    Tetrahedron 0.14, #face, at = %t1;
    Cube 0.14, #face, at = %t2;
    Octahedron 0.14, #face, at = %t3;
    Dodecahedron 0.14, #face, at = %t4;
    Icosahedron 0.14, #face, at = %t5;

    Tetrahedron 0.14, #wire, wireframe = 0.006, at = %m1;
    Cube 0.14, #wire, wireframe = 0.006, at = %m2;
    Octahedron 0.14, #wire, wireframe = 0.006, at = %m3;
    Dodecahedron 0.14, #wire, wireframe = 0.006, at = %m4;
    Icosahedron 0.14, #wire, wireframe = 0.006, at = %m5;

    Tetrahedron 0.14, #face, edges = 0.006, edge_material = #wire, at = %b1;
    Cube 0.14, #face, edges = 0.006, edge_material = #wire, at = %b2;
    Octahedron 0.14, #face, edges = 0.006, edge_material = #wire, at = %b3;
    Dodecahedron 0.14, #face, edges = 0.006, edge_material = #wire, at = %b4;
    Icosahedron 0.14, #face, edges = 0.006, edge_material = #wire, at = %b5;
}
