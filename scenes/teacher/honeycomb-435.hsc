// {4,3,5} for the classroom: faces of tinted glass and edges coloured by cell
// (face_colors and colors count round the same shells about the base cell),
// a light carried by the camera, and the far cells averaged beyond the
// walk's horizon (docs/honeycombs.md).
//   hscene render scenes/teacher/honeycomb-435.hsc -o honeycomb-435.png
Globals {
    resolution = (480, 480);
    from = (0.02, 0.03, 0.01);
    to = (0.1, 0.14, 0.4);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0.25, 0.25, 0.25);
    recursion_depth = 10;
}

BRDFs {
    gold: ambient = (0.4, 0.3, 0.12), diffuse = (0.95, 0.75, 0.35),
          specular = (1, 1, 1), shininess = 40;
    teal: ambient = (0.1, 0.3, 0.3), diffuse = (0.25, 0.75, 0.7),
          specular = (1, 1, 1), shininess = 40;
    rose: ambient = (0.35, 0.12, 0.2), diffuse = (0.85, 0.3, 0.5),
          specular = (1, 1, 1), shininess = 40;
    amber_glass: specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.9,
                 absorption = (0.05, 0.25, 0.9);
    teal_glass: specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.9,
                absorption = (0.9, 0.1, 0.2);
    rose_glass: specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.9,
                absorption = (0.1, 0.8, 0.4);
}

Lights {
    camera, (1, 1, 1), (0.6, 0.6, 0.6), irradiance_at = 0.5, near = 0.3;
}

Objects {
    Honeycomb {4,3,5}, #gold, edges = 0.025, vertices = 0.045,
        colors = (#gold, #teal, #rose),
        face_colors = (#amber_glass, #teal_glass, #rose_glass);
}
