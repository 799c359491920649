// Beyond the thesis (its "further work", SPEC 3.4): an area light with soft
// shadows, and checker textures.
//
// A checkered h-plane below the eye, a checkered sphere and a bunny mesh
// on it, lit by a spherical area light of hyperbolic radius 0.12. The
// shadows have penumbras: from their edges only part of the light sphere is
// visible. The checker cells are squares of side 0.25 in Fermi coordinates
// of each object's own frame, so the pattern moves with the object; on the
// plane the cells shrink towards the absolute, as every length does in the
// ball.
Globals {
    resolution = (480, 360);
    window_size = (1.2, 0.9);
    net_type = 0;
    from = %eye;
    to = %target;
    background = (0.05, 0.06, 0.1);
    ambient = (0.25, 0.25, 0.25);
    recursion_depth = 1;
}

BRDFs {
    floor: ambient = (0.3, 0.3, 0.3), diffuse = (0.9, 0.9, 0.85), specular = (0.2, 0.2, 0.2),
           shininess = 10, checker = 0.25, checker_diffuse = (0.15, 0.2, 0.45),
           checker_ambient = (0.05, 0.07, 0.15);
    ball:  ambient = (0.3, 0.1, 0.1), diffuse = (0.9, 0.25, 0.2), specular = (0.8, 0.8, 0.8),
           shininess = 60, alpha = 0.15, checker = 0.1, checker_diffuse = (0.95, 0.85, 0.3),
           checker_ambient = (0.3, 0.25, 0.1);
    clay:  ambient = (0.3, 0.24, 0.18), diffuse = (0.85, 0.68, 0.5), specular = (0.3, 0.3, 0.3),
           shininess = 30;
}

Points {
    eye = (0, -0.12, 0.05);
    target = (0, -0.3, 0.34);
    // The floor: the h-plane orthogonal to the y axis 0.6 below the origin
    // (Klein y = -tanh 0.6; three of its points, in ball coordinates).
    f1 = (0, -0.291313, 0); f2 = (0, -0.319787, 0.297726); f3 = (0.297726, -0.319787, 0);
    // Resting on the floor, whose ball height there is about -0.341.
    ball = (-0.18, -0.296, 0.35);
    bunny = (0.2, -0.293, 0.33);
    lamp = (-0.4, -0.12, 0.45);
}

Lights {
    sun: %lamp, (6, 6, 5.5), (4, 4, 4), radius = 0.12, samples = 24;
}

Objects {
    Plane %f1, %f2, %f3, #floor;
    Sphere %ball, 0.12, #ball;
    Mesh "meshes/bunny.ply", 0.2, #clay, at = %bunny;
}
