// Predefined planar figures (thesis Figs. 25 and 38): a regular pentagon as
// a wireframe, a Lambert quadrilateral with its edges, a Saccheri
// quadrilateral, and an ideal pentagon, whose vertices lie on the absolute.
Globals {
    resolution = (800, 600);
    window_size = (0.2, 0.15);
    to = (0, 0, 0.1);
    background = (0.03, 0.03, 0.05);
    ambient = (0.2, 0.2, 0.2);
}

BRDFs {
    red:   ambient = (0.3, 0.1, 0.08), diffuse = (0.9, 0.3, 0.2),
           specular = (0.5, 0.5, 0.5), shininess = 20;
    white: ambient = (0.9, 0.9, 0.9), diffuse = (0.9, 0.9, 0.9);
    blue:  ambient = (0.1, 0.15, 0.3), diffuse = (0.3, 0.45, 0.9);
    sky:   ambient = (0.5, 0.5, 0.9), diffuse = (0.25, 0.25, 0.45);
}

Points {
    upper_left = (-0.2, 0.12, 0.5);  upper_right = (0.12, 0.1, 0.5);
    lower_left = (-0.2, -0.15, 0.5); far = (0, 0, 0.85);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities above 1.
Lights {
    (0, 0.1, 0), (6, 6, 6), (4, 4, 4);
    (0, 0.2, 0.7), (3, 3, 3), (1, 1, 1);   // over the ideal pentagon
}

Objects {
    Pentagon 0.3, #white, wireframe = 0.01, at = %upper_left;
    Lambert 0.3, 0.45, #red, edges = 0.01, edge_material = #white, at = %upper_right;
    Saccheri 0.5, 0.35, #blue, at = %lower_left;
    IdealPentagon #sky, edges = 0.04, edge_material = #white, at = %far;
}
