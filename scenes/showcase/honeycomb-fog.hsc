// Showcase: inside the order-5 cubic honeycomb {4,3,5}. The eye sits in
// the middle cell; every cell within three steps of it is drawn as a
// wireframe, lit by a spherical area light just above the eye. Fog of
// distance 2.5 (hyperbolic) fades the far cells into a deep blue: without
// it the exponentially many distant edges would merge into noise.
// Rendered at 1200x1200, 4 samples per pixel, sRGB (the default).
Globals {
    resolution = (1200, 1200);
    fov = 90;
    to = (0, 0, 0.1);
    ambient = (0.2, 0.2, 0.22);
    recursion_depth = 1;
    samples = 4;
    fog_color = (0.02, 0.04, 0.09);
    fog_distance = 2.5;
}

BRDFs {
    edge: ambient = (0.35, 0.3, 0.2), diffuse = (0.95, 0.75, 0.4),
          specular = (1, 1, 1), shininess = 60;
}

Points {
    o = (0, 0, 0);
    tilt = (0.1, 0.1, 0);
    lamp = (0, 0.08, -0.02);
}

Lights {
    %lamp, (0.9, 0.85, 0.8), (0.6, 0.6, 0.6), irradiance_at = 1, radius = 0.05, samples = 8;
}

Objects {
    cells: Tessellation435 3, #edge, wireframe = 0.02;
}

Transformations {
    // Turn the honeycomb so that no edge points straight at the eye.
    axis: hline (%o, %tilt);
    @cells->Rotate(%axis, 0.4);
}
