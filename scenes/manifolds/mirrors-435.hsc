// A kaleidoscope: the cube of {4,3,5} (72-degree dihedral angles) with
// mirror walls. Every ray that meets a wall is reflected back into the
// cube, so the balls and the lamp are seen in the walls, in the walls'
// images, and so on. Five cubes meet round each edge of {4,3,5}, an odd
// number: round an edge, the images come back mirrored, which is why
// this room is a kaleidoscope but not an orbifold (docs/manifolds.md).
//   hscene render scenes/manifolds/mirrors-435.hsc -o mirrors-435.png
Globals {
    resolution = (480, 480);
    samples = 4;
    space = {4,3,5};
    light_reach = 1.5;
    domain = 0.015, #brass;
    from = (0.02, 0.03, 0.01);
    to = (0.1, 0.03, 0.3);
    fov = 100;
    background = (0.02, 0.02, 0.05);
    ambient = (0.1, 0.1, 0.1);
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
    (-0.05, -0.05, 0.05), (1, 0.95, 0.85), (0.3, 0.3, 0.3), irradiance_at = 0.15;
}

Objects {
    Sphere (0.12, 0.05, 0.15), 0.07, #red;
    Sphere (-0.1, 0.1, 0.12), 0.05, #teal;
}
