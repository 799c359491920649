// The unlimited {4,3,5} honeycomb, edges only, from the centre of the base
// cube: the scene `hscene view` is benchmarked on (benches/view.rs). Fly
// with W/A/S/D, R/F and the arrow keys; C prints the camera.
Globals {
    resolution = (480, 270);
    to = (0.1, 0.13, 0.4);
    fov = 90;
    background = (0, 0, 0);
    ambient = (0.4, 0.4, 0.4);
    recursion_depth = 0;
}

BRDFs {
    edge: ambient = (0.4, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45),
          specular = (1, 1, 1), shininess = 40;
}

Lights {
    (0, 0, 0), (6, 6, 6), (4, 4, 4);
}

Objects {
    Honeycomb {4,3,5}, #edge, edges = 0.03;
}
