// The order-5 hexagonal tiling honeycomb {6,3,5} seen from inside a cell: hexagonal tilings,
// 5 around every edge (dihedral angle 72 degrees); at every vertex the vertex
// figure is an icosahedron (12 edges, 20 cells).
// The cells are hexagonal tilings inscribed in horospheres: infinitely
// many faces each, touching the absolute at the cell's ideal centre.
// The origin is the centre of a face (the plane x = 0); the eye sits
// inside the cell on its x < 0 side, looking along the face.
// Faces are translucent glass, edges solid rods (docs/honeycombs.md).
Globals {
    resolution = (400, 400);
    from = (-0.25, 0.02, 0.03);
    to = (-0.25, 0.12, 0.3);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0.6, 0.6, 0.6);
    recursion_depth = 8;
}

BRDFs {
    edge: ambient = (0.38, 0.3, 0.2), diffuse = (0.95, 0.75, 0.5),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.075, 0.2, 0.175), diffuse = (0.105, 0.28, 0.245),
           trans = 0.72;
}

Lights {
    (-0.25, 0.02, 0.03), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {6,3,5}, #edge, edges = 0.025, faces = #glass, vertices = 0.045;
}
