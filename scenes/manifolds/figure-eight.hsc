// Inside the figure-eight knot complement: two regular ideal tetrahedra
// of {3,3,6} glued face to face, their six outer faces glued in pairs.
// The space has one cusp: the domain's five ideal vertices are all the
// same end of the space, where the edges run together into stars that
// never close (each star is the cusp seen down its throat). Rays that
// run into a cusp run out of face crossings and take the space's average
// appearance beyond (docs/manifolds.md, "The horizon").
//   hscene render scenes/manifolds/figure-eight.hsc -o figure-eight.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = figure_eight;
    domain = 0.03, #brass;
    from = (-0.05, -0.05, -0.02);
    to = (0.12, 0.12, 0.24);
    fov = 100;
    background = (0.02, 0.02, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 2;
}

BRDFs {
    brass: ambient = (0.4, 0.32, 0.16), diffuse = (0.6, 0.45, 0.22),
           specular = (0.8, 0.8, 0.7), shininess = 40;
    red: ambient = (0.5, 0.1, 0.1), diffuse = (0.9, 0.2, 0.15),
         specular = (0.6, 0.6, 0.6), shininess = 60;
    teal: ambient = (0.1, 0.4, 0.4), diffuse = (0.2, 0.7, 0.7),
          specular = (0.6, 0.6, 0.6), shininess = 60;
    white: ambient = (0.5, 0.5, 0.5), diffuse = (0.85, 0.85, 0.85),
           specular = (0.6, 0.6, 0.6), shininess = 60;
}

Lights {
    (0.05, -0.1, 0.05), (1, 0.95, 0.85), (0.4, 0.4, 0.4), irradiance_at = 0.5;
}

Objects {
    Sphere (0.2, 0, 0.05), 0.1, #red;
    Sphere (-0.15, 0.15, 0.1), 0.08, #teal;
    Sphere (0, -0.2, -0.1), 0.09, #white;
}
