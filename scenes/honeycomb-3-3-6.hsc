// The order-6 tetrahedral honeycomb {3,3,6} seen from inside a cell: tetrahedra,
// 6 around every edge (dihedral angle 60 degrees); at every vertex the vertex
// figure is the triangular tiling, a Euclidean tiling, so the vertices are
// ideal: the edges run out to the absolute and meet there.
// Faces are translucent glass, edges solid rods (docs/honeycombs.md).
Globals {
    resolution = (400, 400);
    from = (0.02, 0.03, 0.01);
    to = (0.1, 0.14, 0.4);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0.6, 0.6, 0.6);
    recursion_depth = 8;
}

BRDFs {
    edge: ambient = (0.38, 0.28, 0.12), diffuse = (0.95, 0.7, 0.3),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.075, 0.2, 0.1), diffuse = (0.105, 0.28, 0.14),
           trans = 0.72;
}

Lights {
    (0.02, 0.03, 0.01), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {3,3,6}, #edge, edges = 0.025, faces = #glass;
}
