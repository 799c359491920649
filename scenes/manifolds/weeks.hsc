// Inside the Weeks manifold, the closed hyperbolic 3-manifold of least
// volume (0.9427), given by the face pairings of its Dirichlet domain as
// SnapPy computes them (weeks.json: 18 faces, 26 vertices, 42 edges; how
// to write such a file for any manifold is in docs/manifolds.md).
//   hscene render scenes/manifolds/weeks.hsc -o weeks.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = "weeks.json";
    light_reach = 1.5;
    domain = 0.02, #brass;
    from = (0.01, 0.02, 0.0);
    to = (0.05, 0.03, 0.3);
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
}

Lights {
    (-0.05, 0.08, -0.05), (1, 0.95, 0.85), (0.4, 0.4, 0.4), irradiance_at = 0.3;
}

Objects {
    Sphere (0.12, -0.05, 0.08), 0.07, #red;
    Sphere (-0.1, -0.08, 0.05), 0.06, #teal;
}
