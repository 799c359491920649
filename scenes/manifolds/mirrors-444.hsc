// The cell of {4,4,4} with mirror walls: a cell inscribed in a horosphere,
// its infinitely many square faces tiling that horosphere and its centre
// an ideal point. Four cells meet round each edge, an even number, so the
// mirrored cell is an orbifold: every image is seen the same however the
// rays reach it. The face through the origin is the plane x = 0 and the
// cell lies on its x < 0 side, its ideal centre at (-1, 0, 0): looking
// that way, the walls recede into the cusp (docs/manifolds.md).
//   hscene render scenes/manifolds/mirrors-444.hsc -o mirrors-444.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = {4,4,4};
    light_reach = 2;
    domain = 0.02, #brass;
    from = (-0.08, 0.03, 0.02);
    to = (-0.4, 0.1, 0.12);
    fov = 100;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
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
    (-0.2, 0.0, 0.1), (1, 0.95, 0.85), (0.4, 0.4, 0.4), irradiance_at = 0.4;
}

Objects {
    Sphere (-0.3, 0.12, 0.06), 0.1, #red;
    Sphere (-0.25, -0.12, 0.02), 0.09, #teal;
    Sphere (-0.12, 0.02, 0.2), 0.06, #teal;
}
