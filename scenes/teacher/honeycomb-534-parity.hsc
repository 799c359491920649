// {5,3,4} two-coloured by parity (color_by = parity): four cells round each
// edge, so neighbours across every face can differ. The base cell's walls are
// clear and its neighbours' amber, the next layer clear again; edges gold in
// even cells, teal in odd ones. A light carried by the camera; the far cells
// averaged beyond the walk's horizon (docs/honeycombs.md).
//   hscene render scenes/teacher/honeycomb-534-parity.hsc -o honeycomb-534-parity.png
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
    clear: specular = (0.4, 0.4, 0.4), shininess = 80, trans = 0.95;
    amber_glass: ambient = (0.12, 0.08, 0.02), diffuse = (0.3, 0.2, 0.05),
                 specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.8,
                 absorption = (0.02, 0.15, 0.6);
}

Lights {
    camera, (1, 1, 1), (0.6, 0.6, 0.6), irradiance_at = 0.5, near = 0.3;
}

Objects {
    Honeycomb {5,3,4}, #gold, edges = 0.025, vertices = 0.045,
        colors = (#gold, #teal), face_colors = (#clear, #amber_glass),
        color_by = parity;
}
