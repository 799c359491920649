// A honeycomb for a 3D printer: edges and vertex balls only. `hscene export`
// turns it into an STL, 3MF, OBJ or glTF of the Poincaré ball (docs/export.md); `render` shows
// the same scene from inside.
Globals {
    resolution = (400, 400);
    from = (0.02, 0.03, 0.01);
    to = (0.06, 0.09, 0.4);
    fov = 100;
    ambient = (0.35, 0.35, 0.35);
}

BRDFs {
    gold: ambient = (0.4, 0.3, 0.12), diffuse = (0.95, 0.75, 0.35),
          specular = (1, 1, 1), shininess = 40;
}

Lights {
    (0.1, 0.2, -0.1), (4, 4, 4), (3, 3, 3);
}

Objects {
    Honeycomb {5,3,4}, #gold, edges = 0.06, vertices = 0.09;
}
