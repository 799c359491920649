// Thesis Fig. 29, right panel (net 0): a mirror-like h-dodecahedron inside
// a tilted ring of six h-spheres, above a reflecting h-plane, rendered WITH
// reflections (recursion depth 1). The left panel, the same scene without
// reflections, is fig29-reflection-depth0.hsc.
//
// Hyperbolic property: reflection is computed exactly in hyperbolic space.
// A reflected ray leaves the hit point along the h-line (a circular arc in
// the ball) that makes the mirror angle with the surface in the tangent
// space there; since the model is conformal, that angle is the Euclidean
// angle in the ball. Each sphere shows the dodecahedron and its neighbours,
// the dodecahedron's flat faces each show a piece of the ring, and the
// floor (an h-plane: a sphere orthogonal to the absolute) mirrors the lot.
Globals {
    resolution = (400, 300);
    window_size = (0.1, 0.075);   // Euclidean, on the plane z = 0.1: 53° wide
    net_type = 0;
    to = (0, 0, 0.1);
    background = (0.02, 0.02, 0.04);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 1;
}

BRDFs {
    mirror: ambient = (0.1, 0.1, 0.12), diffuse = (0.25, 0.25, 0.3),
            specular = (1, 1, 1), shininess = 80, alpha = 0.7;
    red:    ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.2, 0.15),
            specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    yellow: ambient = (0.3, 0.25, 0.05), diffuse = (0.9, 0.8, 0.2),
            specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    green:  ambient = (0.05, 0.25, 0.1), diffuse = (0.2, 0.8, 0.3),
            specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    blue:   ambient = (0.05, 0.1, 0.3), diffuse = (0.2, 0.4, 0.95),
            specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    floor:  ambient = (0.12, 0.12, 0.12), diffuse = (0.35, 0.35, 0.35),
            specular = (0.3, 0.3, 0.3), shininess = 10, alpha = 0.5;
}

Points {
    centre = (0, 0, 0.604368);     // tanh(0.7): distance 1.4 from the eye
    // The ring: distance 0.6 from the centre, tilted 22° towards the eye.
    s1 = (0.156676, 0.018156, 0.678178);
    s2 = (0.030386, 0.050056, 0.752387);
    s3 = (-0.108270, 0.037572, 0.723347);
    s4 = (-0.189027, -0.021904, 0.584989);
    s5 = (-0.057534, -0.094778, 0.415465);
    s6 = (0.167647, -0.058178, 0.500607);
    // Three points of the floor plane, below the ring.
    f1 = (-0.5, -0.17, 0.3); f2 = (0, -0.17, 0.8); f3 = (0.5, -0.17, 0.3);
    lamp = (-0.15, 0.3, 0.25);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9): the scene is about
// 1.2 from the lamp and 1.4 from the eye, hence the intensities.
Lights {
    %lamp, (18, 18, 18), (15, 15, 15);
    (0, 0.05, 0), (8, 8, 8), (4, 4, 4);
}

Objects {
    Dodecahedron 0.3, #mirror, at = %centre;
    Sphere %s1, 0.11, #red;
    Sphere %s2, 0.11, #yellow;
    Sphere %s3, 0.11, #green;
    Sphere %s4, 0.11, #blue;
    Sphere %s5, 0.11, #red;
    Sphere %s6, 0.11, #yellow;
    Plane %f1, %f2, %f3, #floor;
}
