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
    ambient = (0.35, 0.35, 0.35);
    recursion_depth = 12;
}

BRDFs {
    glass: ambient = (0.01, 0.02, 0.04), diffuse = (0.03, 0.06, 0.12),
           specular = (0.4, 0.4, 0.4), shininess = 80, trans = 0.88;
    gold: ambient = (0.4, 0.3, 0.12), diffuse = (0.95, 0.75, 0.35),
          specular = (1, 1, 1), shininess = 40;
    cyan: ambient = (0.1, 0.3, 0.35), diffuse = (0.25, 0.75, 0.85),
          specular = (1, 1, 1), shininess = 40;
    magenta: ambient = (0.35, 0.12, 0.3), diffuse = (0.85, 0.3, 0.75),
             specular = (1, 1, 1), shininess = 40;
}

Lights {
    (-0.2, 0.2, -0.1), (4, 4, 4), (3, 3, 3);
}

Objects {
    // Edges and vertices coloured by the cell's shell around the base cell:
    // gold for the base cell, then cyan, magenta, gold, ... outwards.
    Honeycomb {6,3,5}, #gold, edges = 0.025, vertices = 0.045, faces = #glass,
        colors = (#gold, #cyan, #magenta);
}
