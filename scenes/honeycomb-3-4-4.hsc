// The order-4 octahedral honeycomb {3,4,4} seen from inside a cell: octahedra,
// 4 around every edge (dihedral angle 90 degrees); at every vertex the vertex
// figure is the square tiling, a Euclidean tiling, so the vertices are
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
    edge: ambient = (0.38, 0.32, 0.16), diffuse = (0.95, 0.8, 0.4),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.1, 0.2, 0.225), diffuse = (0.14, 0.28, 0.315),
           trans = 0.72;
}

Lights {
    (0.02, 0.03, 0.01), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {3,4,4}, #edge, edges = 0.025, faces = #glass;
}
