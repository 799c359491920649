// A fly-through of the {4,3,5} honeycomb that loops: from the centre of the
// base cube straight through the middle of its +z face, 23/24 of the way to
// the next cube's centre (twice the inradius, 1.061275) in 24 frames; the
// frame after the last would be the first again, since the step is a
// symmetry of the honeycomb (docs/honeycombs.md, "Measures").
// The camera carries its light, bounded by `near` so that no frame goes
// white when a face passes close; faces are glass. (Colours by cell would
// break the loop: classes count from the base cell, and the next cube is
// one shell out.)
//   hscene render scenes/video/flythrough-435.hsc -o flythrough.gif
Globals {
    resolution = (240, 240);
    frames = 24;
    to = (0, 0, 0.3);
    fov = 100;
    background = (0, 0, 0);
    ambient = (0.3, 0.3, 0.3);
    recursion_depth = 6;
}

Transformations {
    axis: hline ((0, 0, 0), (0, 0, 0.5));
    @camera->Translate(%axis, 1.017055), animate;
}

BRDFs {
    edge: ambient = (0.4, 0.3, 0.15), diffuse = (0.9, 0.7, 0.35),
          specular = (0.6, 0.6, 0.6), shininess = 40;
    glass: ambient = (0.02, 0.03, 0.05), diffuse = (0.05, 0.08, 0.12),
           specular = (0.5, 0.5, 0.5), shininess = 80, trans = 0.85;
}

Lights {
    camera, (1, 1, 1), (0.6, 0.6, 0.6), irradiance_at = 0.4, near = 0.4;
}

Objects {
    Honeycomb {4,3,5}, #edge, edges = 0.03, vertices = 0.05, faces = #glass;
}
