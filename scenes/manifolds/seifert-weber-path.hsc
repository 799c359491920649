// Seifert-Weber space path-traced: light bounces between the balls, the
// brass edges and their images in every direction, each bounce carried
// across the faces like the view rays; the lamp's images light it
// (docs/manifolds.md).
//   hscene render scenes/manifolds/seifert-weber-path.hsc -o seifert-weber-path.png
Globals {
    resolution = (360, 360);
    samples = 64;
    integrator = path;
    space = seifert_weber;
    domain = 0.05, #brass;
    from = (0, 0, 0);
    to = (0.1, 0.03, 0.3);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0, 0, 0);
}

BRDFs {
    brass: diffuse = (0.7, 0.5, 0.25), specular = (0.3, 0.3, 0.25), shininess = 60;
    red: diffuse = (0.85, 0.2, 0.15);
    teal: diffuse = (0.2, 0.7, 0.7);
    mirror: diffuse = (0.05, 0.05, 0.05), specular = (0.9, 0.9, 0.9), alpha = 0.9;
}

Lights {
    (0.05, 0.1, -0.1), (1, 0.95, 0.85), (0, 0, 0), irradiance_at = 0.6;
}

Objects {
    Sphere (0.25, 0, 0.1), 0.12, #red;
    Sphere (-0.2, 0.2, 0.15), 0.1, #teal;
    Sphere (0, -0.25, -0.2), 0.14, #mirror;
}
