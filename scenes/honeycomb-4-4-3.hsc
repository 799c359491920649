// The square tiling honeycomb {4,4,3} seen from inside a cell: square tilings,
// 3 around every edge (dihedral angle 120 degrees); at every vertex the vertex
// figure is a cube (8 edges, 6 cells).
// The cells are square tilings inscribed in horospheres: infinitely
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
    edge: ambient = (0.36, 0.36, 0.36), diffuse = (0.9, 0.9, 0.9),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.225, 0.15, 0.05), diffuse = (0.315, 0.21, 0.07),
           trans = 0.72;
}

Lights {
    (-0.25, 0.02, 0.03), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {4,4,3}, #edge, edges = 0.025, faces = #glass, vertices = 0.045;
}
