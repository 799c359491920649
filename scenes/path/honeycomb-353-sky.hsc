// The icosahedral honeycomb {3,5,3}, path-traced under a sky: the only light
// is the background, radiance arriving from the sphere at infinity. The clay
// edges and vertices are lit by the part of the sky that their neighbours
// do not hide, and by each other; where many edges meet, at the vertices,
// less sky gets through (ambient occlusion, computed rather than faked).
//
//   hscene render scenes/path/honeycomb-353-sky.hsc -o sky.png
Globals {
    resolution = (400, 400);
    samples = 64;
    from = (0.01, 0.02, 0.0);
    to = (0.05, 0.08, 0.4);
    fov = 100;
    integrator = path;
    background = (0.55, 0.65, 0.9);
}

BRDFs {
    clay: diffuse = (0.85, 0.6, 0.4);
}

Objects {
    Honeycomb {3,5,3}, #clay, edges = 0.03, vertices = 0.06;
}
