// Inside the Seifert-Weber dodecahedral space: one {5,3,5} dodecahedron
// whose opposite faces are glued with a 3/10 turn. Every ray that leaves
// by a face comes back through the opposite one, so the three balls and
// the lamp are seen again and again, in every direction, as far as the
// eye resolves (docs/manifolds.md).
//   hscene render scenes/manifolds/seifert-weber.hsc -o seifert-weber.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = seifert_weber;
    domain = 0.04, #brass;
    from = (0, 0, 0);
    to = (0.1, 0.03, 0.3);
    fov = 100;
    background = (0.02, 0.02, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 2;
}

BRDFs {
    brass: ambient = (0.5, 0.4, 0.2), diffuse = (0.8, 0.6, 0.3),
           specular = (0.8, 0.8, 0.7), shininess = 40;
    red: ambient = (0.5, 0.1, 0.1), diffuse = (0.9, 0.2, 0.15),
         specular = (0.6, 0.6, 0.6), shininess = 60;
    teal: ambient = (0.1, 0.4, 0.4), diffuse = (0.2, 0.7, 0.7),
          specular = (0.6, 0.6, 0.6), shininess = 60;
    white: ambient = (0.5, 0.5, 0.5), diffuse = (0.85, 0.85, 0.85),
           specular = (0.6, 0.6, 0.6), shininess = 60;
}

Lights {
    (0.05, 0.1, -0.1), (1, 0.95, 0.85), (0.5, 0.5, 0.5), irradiance_at = 0.6;
}

Objects {
    Sphere (0.25, 0, 0.1), 0.12, #red;
    Sphere (-0.2, 0.2, 0.15), 0.1, #teal;
    Sphere (0, -0.25, -0.2), 0.14, #white;
}
