// The order-5 cubic honeycomb {4,3,5} seen from inside a cell: cubes,
// 5 around every edge (dihedral angle 72 degrees); at every vertex the vertex
// figure is an icosahedron (12 edges, 20 cells).
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
    edge: ambient = (0.38, 0.3, 0.16), diffuse = (0.95, 0.75, 0.4),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.075, 0.125, 0.225), diffuse = (0.105, 0.175, 0.315),
           trans = 0.72;
}

Lights {
    (0.02, 0.03, 0.01), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {4,3,5}, #edge, edges = 0.025, faces = #glass, vertices = 0.045;
}
