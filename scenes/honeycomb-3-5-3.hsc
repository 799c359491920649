// The icosahedral honeycomb {3,5,3} seen from inside a cell: icosahedra,
// 3 around every edge (dihedral angle 120 degrees); at every vertex the vertex
// figure is a dodecahedron (20 edges, 12 cells).
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
    edge: ambient = (0.38, 0.34, 0.16), diffuse = (0.95, 0.85, 0.4),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.225, 0.0875, 0.0625), diffuse = (0.315, 0.1225, 0.0875),
           trans = 0.72;
}

Lights {
    (0.02, 0.03, 0.01), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {3,5,3}, #edge, edges = 0.025, faces = #glass, vertices = 0.045;
}
