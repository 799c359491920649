// Rods: the points within a hyperbolic distance of an h-segment. Three rods
// run from a centre out to ideal points on the absolute (no cap there), a
// triangle of finite rods frames the centre, and a small sphere marks it.
Globals {
    resolution = (640, 640);
    window_size = (0.15, 0.15);
    to = (0, 0, 0.1);
    background = (0.03, 0.03, 0.06);
    ambient = (0.15, 0.15, 0.15);
}

BRDFs {
    brass: ambient = (0.3, 0.25, 0.1), diffuse = (0.8, 0.65, 0.25),
           specular = (1, 1, 1), shininess = 50;
    steel: ambient = (0.2, 0.2, 0.25), diffuse = (0.5, 0.55, 0.6),
           specular = (1, 1, 1), shininess = 80, alpha = 0.2;
    red:   ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.15, 0.1),
           specular = (0.6, 0.6, 0.6), shininess = 30;
}

Points {
    centre = (0, 0, 0.45);
    east = (1, 0, 0);                       // ideal points
    north = (0, 1, 0);
    south = (0, -1, 0);
    a = (-0.15, -0.1, 0.4); b = (0.15, -0.1, 0.4); c = (0, 0.16, 0.4);
    lamp = (0.1, 0.3, 0.05);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities above 1.
Lights {
    sun: %lamp, (4, 4, 4), (4, 4, 4);
    (0, 0, 0), (2, 2, 2), (1, 1, 1);
}

Objects {
    Rod %centre, %east, 0.015, #brass;       // out to the absolute
    Rod %centre, %north, 0.015, #brass;
    Rod %centre, %south, 0.015, #brass;
    Rod %a, %b, 0.01, #steel;                // a finite triangle
    Rod %b, %c, 0.01, #steel;
    Rod %c, %a, 0.01, #steel;
    Sphere %centre, 0.07, #red;
}
