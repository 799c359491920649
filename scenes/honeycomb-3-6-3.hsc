// The triangular tiling honeycomb {3,6,3} seen from inside a cell: triangular tilings,
// 3 around every edge (dihedral angle 120 degrees); at every vertex the vertex
// figure is the hexagonal tiling, a Euclidean tiling, so the vertices are
// ideal: the edges run out to the absolute and meet there.
// The cells are triangular tilings inscribed in horospheres: infinitely
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
    edge: ambient = (0.38, 0.34, 0.2), diffuse = (0.95, 0.85, 0.5),
          specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.075, 0.1125, 0.2375), diffuse = (0.105, 0.1575, 0.3325),
           trans = 0.72;
}

Lights {
    (-0.25, 0.02, 0.03), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {3,6,3}, #edge, edges = 0.025, faces = #glass;
}
