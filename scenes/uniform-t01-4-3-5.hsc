// The truncated order-5 cubic honeycomb t0,1{4,3,5}: truncated cubes
// (octagons and triangles) and icosahedra, one icosahedron and five
// truncated cubes at every vertex, where the cubes' corners were.
// Faces are translucent glass, edges and vertices gold (docs/honeycombs.md,
// "Uniform honeycombs").
Globals {
    resolution = (400, 400);
    from = (0.02, 0.03, 0.01);
    to = (0.06, 0.09, 0.4);
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
}

Lights {
    (0.1, 0.2, -0.1), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {4,3,5}, #gold, edges = 0.02, vertices = 0.035, faces = #glass,
        rings = (0, 1);
}
