// {3,5,3} for the classroom: faces of tinted glass and edges coloured by cell
// (face_colors and colors count round the same shells about the base cell;
// the base cell's own faces are clear, so that the eye sees out),
// a light carried by the camera, and the far cells averaged beyond the
// walk's horizon (docs/honeycombs.md).
//   hscene render scenes/teacher/honeycomb-353.hsc -o honeycomb-353.png
Globals {
    resolution = (480, 480);
    from = (0.02, 0.03, 0.01);
    to = (0.1, 0.14, 0.4);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0.4, 0.4, 0.4);
    recursion_depth = 10;
}

BRDFs {
    gold: ambient = (0.4, 0.3, 0.12), diffuse = (0.95, 0.75, 0.35),
          specular = (1, 1, 1), shininess = 40;
    teal: ambient = (0.1, 0.3, 0.3), diffuse = (0.25, 0.75, 0.7),
          specular = (1, 1, 1), shininess = 40;
    rose: ambient = (0.35, 0.12, 0.2), diffuse = (0.85, 0.3, 0.5),
          specular = (1, 1, 1), shininess = 40;
    clear: specular = (0.4, 0.4, 0.4), shininess = 80, trans = 0.95;
    amber_glass: ambient = (0.12, 0.08, 0.02), diffuse = (0.3, 0.2, 0.05),
                 specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.8,
                 absorption = (0.02, 0.15, 0.6);
    teal_glass: ambient = (0.02, 0.1, 0.1), diffuse = (0.05, 0.25, 0.25),
                specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.8,
                absorption = (0.6, 0.05, 0.1);
    rose_glass: ambient = (0.12, 0.03, 0.07), diffuse = (0.3, 0.08, 0.18),
                specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.8,
                absorption = (0.05, 0.6, 0.3);
}

Lights {
    camera, (1, 1, 1), (0.6, 0.6, 0.6), irradiance_at = 0.5, near = 0.3;
}

Objects {
    Honeycomb {3,5,3}, #gold, edges = 0.025, vertices = 0.045,
        colors = (#gold, #teal, #rose),
        face_colors = (#clear, #teal_glass, #rose_glass, #amber_glass);
}
