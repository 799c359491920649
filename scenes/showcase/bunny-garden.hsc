// Showcase: the Stanford bunny and a glossy checkered ball on a checkered
// h-plane, under a warm spherical area light, in a light evening fog. The
// floor's checker cells shrink towards the absolute, as every length does
// in the ball; the fog (distance 5) turns the far floor into a horizon.
// Rendered at 1200x900, 4 samples per pixel, sRGB (the default).
Globals {
    resolution = (1200, 900);
    fov = 95;
    net_type = 0;
    from = %eye;
    to = %target;
    ambient = (0.2, 0.2, 0.22);
    recursion_depth = 2;
    samples = 4;
    fog_color = (0.3, 0.33, 0.42);
    fog_distance = 5;
}

BRDFs {
    floor: ambient = (0.25, 0.25, 0.25), diffuse = (0.9, 0.9, 0.85), specular = (0.2, 0.2, 0.2),
           shininess = 10, checker = 0.25, checker_diffuse = (0.12, 0.2, 0.45),
           checker_ambient = (0.05, 0.07, 0.15);
    ball:  ambient = (0.3, 0.1, 0.1), diffuse = (0.9, 0.25, 0.2), specular = (0.8, 0.8, 0.8),
           shininess = 60, alpha = 0.2, checker = 0.1, checker_diffuse = (0.95, 0.85, 0.3),
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
    sun: %lamp, (1.8, 1.6, 1.35), (1, 1, 0.9), irradiance_at = 0.7, radius = 0.12, samples = 16;
}

Objects {
    Plane %f1, %f2, %f3, #floor;
    Sphere %ball, 0.12, #ball;
    Mesh "../meshes/bunny.ply", 0.2, #clay, at = %bunny;
}
