// The truncated order-6 tetrahedral honeycomb t0,1{3,3,6}: truncated
// tetrahedra and hexagonal tilings. Truncating {3,3,6} cuts off its ideal
// vertices, so every vertex is finite, and each cut leaves a hexagonal
// tiling, a cell inscribed in a horosphere.
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
    Honeycomb {3,3,6}, #gold, edges = 0.02, vertices = 0.035, faces = #glass,
        rings = (0, 1);
}
