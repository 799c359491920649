// The order-5 cubic honeycomb {4,3,5}, path-traced from inside a cell: the
// faces are glass (index 1.3: Fresnel reflection at grazing angles,
// refraction through every face), the edges and vertices of the base cell
// gold and those of the next shell of cells glowing lamps, then gold again
// (`colors` counts shells outwards). The only light is the glowing edges'
// own: it travels through layer after layer of glass, reflects off the gold
// edges and is refracted at each face, none of which Whitted's point lights
// and ambient constant can show.
//
//   hscene render scenes/path/honeycomb-435-glass.hsc -o glass.png
Globals {
    resolution = (400, 400);
    samples = 64;
    from = (0.02, 0.03, 0.01);
    to = (0.06, 0.09, 0.4);
    fov = 100;
    integrator = path;
    background = (0.01, 0.01, 0.02);
}

BRDFs {
    glass: diffuse = (0.02, 0.04, 0.08), trans = 0.9, refraction = 1.3;
    gold: diffuse = (0.9, 0.7, 0.35), specular = (0.3, 0.25, 0.15), shininess = 40;
    lamp: diffuse = (0.5, 0.5, 0.5), emission = (6, 5, 4);
}

Objects {
    Honeycomb {4,3,5}, #gold, edges = 0.025, vertices = 0.05, faces = #glass,
        colors = (#gold, #lamp);
}
