// Thesis Fig. 40, left (net 0): the test scene "h-spheres" of the thesis's
// timing table (its Table 2): 16 h-spheres, 5 lights, recursion depth 1.
// The spheres (radius 0.15, half of them mirror-like) sit at the nodes of
// a 4 x 4 equidistant grid, 0.5 apart, in the h-plane at distance 1.3 in
// front of the eye; four lamps hang at the corners and one sits by the eye.
//
// Hyperbolic property: every sphere has the same hyperbolic radius, but the
// outer ones are farther from the eye (the grid lies on an h-plane, which
// in the ball is a sphere orthogonal to the absolute, curving away from
// the eye), so they look smaller. Each mirror sphere reflects its
// neighbours along h-lines. SPEC §6: the thesis needed 75.7 s for this
// scene at 1000 x 1000 on a Core2 Duo; see docs/gallery.md for ours.
Globals {
    resolution = (400, 400);
    window_size = (0.12, 0.12);    // Euclidean, on the plane z = 0.1: 62° wide
    net_type = 0;
    to = (0, 0, 0.1);
    background = (0.02, 0.02, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 1;
}

BRDFs {
    red:    ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.2, 0.15),
            specular = (0.8, 0.8, 0.8), shininess = 40;
    mirror: ambient = (0.1, 0.1, 0.12), diffuse = (0.35, 0.4, 0.5),
            specular = (1, 1, 1), shininess = 80, alpha = 0.6;
}

Points {
    s1 = (-0.204409, 0.204409, 0.647519); s2 = (-0.070173, 0.228432, 0.622344);
    s3 = (0.070173, 0.228432, 0.622344); s4 = (0.204409, 0.204409, 0.647519);
    s5 = (-0.228432, 0.070173, 0.622344); s6 = (-0.081675, 0.081675, 0.583111);
    s7 = (0.081675, 0.081675, 0.583111); s8 = (0.228432, 0.070173, 0.622344);
    s9 = (-0.228432, -0.070173, 0.622344); s10 = (-0.081675, -0.081675, 0.583111);
    s11 = (0.081675, -0.081675, 0.583111); s12 = (0.228432, -0.070173, 0.622344);
    s13 = (-0.204409, -0.204409, 0.647519); s14 = (-0.070173, -0.228432, 0.622344);
    s15 = (0.070173, -0.228432, 0.622344); s16 = (0.204409, -0.204409, 0.647519);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    (-0.2, 0.2, 0.4), (8, 8, 8), (5, 5, 5);
    (0.2, 0.2, 0.4), (8, 8, 8), (5, 5, 5);
    (-0.2, -0.2, 0.4), (8, 8, 8), (5, 5, 5);
    (0.2, -0.2, 0.4), (8, 8, 8), (5, 5, 5);
    (0, 0.05, 0), (8, 8, 8), (4, 4, 4);
}

Objects {
    Sphere %s1, 0.15, #red;     Sphere %s2, 0.15, #mirror;
    Sphere %s3, 0.15, #red;     Sphere %s4, 0.15, #mirror;
    Sphere %s5, 0.15, #mirror;  Sphere %s6, 0.15, #red;
    Sphere %s7, 0.15, #mirror;  Sphere %s8, 0.15, #red;
    Sphere %s9, 0.15, #red;     Sphere %s10, 0.15, #mirror;
    Sphere %s11, 0.15, #red;    Sphere %s12, 0.15, #mirror;
    Sphere %s13, 0.15, #mirror; Sphere %s14, 0.15, #red;
    Sphere %s15, 0.15, #mirror; Sphere %s16, 0.15, #red;
}
