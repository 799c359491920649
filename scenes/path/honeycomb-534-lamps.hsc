// The order-4 dodecahedral honeycomb {5,3,4}, path-traced from near the
// centre of a cell: white matte edges and vertices, and the edges and
// vertices of every other shell of cells glowing (`colors` counts shells
// outwards; the faces are clear, index-1 sheets that let everything through).
// The light falls off as 1/sinh² r, so each glowing edge lights its matte
// neighbours and little more, a soft glow that Whitted's integrator
// replaces with a constant. Glowing edges are not h-spheres, so only the
// paths' own directions find them: this picture needs many samples.
//
//   hscene render scenes/path/honeycomb-534-lamps.hsc -o lamps.png
Globals {
    resolution = (400, 400);
    samples = 256;
    from = (0.01, 0.02, 0.0);
    to = (0.05, 0.08, 0.4);
    fov = 100;
    integrator = path;
    background = (0, 0, 0);
}

BRDFs {
    white: diffuse = (0.8, 0.8, 0.78);
    lamp: diffuse = (0.8, 0.8, 0.78), emission = (2, 1.3, 0.6);
    clear: trans = 1, refraction = 1;
}

Objects {
    Honeycomb {5,3,4}, #white, edges = 0.04, vertices = 0.08, faces = #clear,
        colors = (#lamp, #white);
}
