// Inside the Whitehead link complement: one regular ideal octahedron of
// {3,4,4} (right dihedral angles), its eight faces glued in four pairs.
// The space has two cusps, one for each component of the link: the
// octahedron's six ideal vertices fall into the classes {w0, w5} and
// {w1, w2, w3, w4} (docs/manifolds.md). Looking at w0 = (½, ½, 1/√2),
// the edges run together into the cusp's star.
//   hscene render scenes/manifolds/whitehead.hsc -o whitehead.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = whitehead;
    domain = 0.03, #brass;
    from = (-0.05, -0.05, -0.05);
    to = (0.1, 0.1, 0.14);
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
    Sphere (0.25, 0, 0.05), 0.1, #red;
    Sphere (-0.2, 0.2, 0.1), 0.08, #teal;
    Sphere (0, -0.25, -0.1), 0.09, #white;
}
