// Beyond the thesis (SPEC 3.4): an animation. The observer orbits an
// h-dodecahedron once in 36 frames, about the vertical h-line through its
// centre (`@camera->Rotate(..., 2π·35/36), animate`: frame k turns by
// 2π·k/36, so the sequence loops without a repeated frame).
//
//   hscene render scenes/orbit.hsc -o orbit.png     # orbit-0000.png ... orbit-0035.png
//   hscene render scenes/orbit.hsc --frame 9 -o quarter.png
Globals {
    frames = 36;
    resolution = (320, 320);
    window_size = (0.5, 0.5);
    net_type = 0;
    from = %eye;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    face: ambient = (0.15, 0.2, 0.35), diffuse = (0.3, 0.5, 0.9),
          specular = (0.8, 0.8, 0.8), shininess = 40, checker = 0.2,
          checker_diffuse = (0.9, 0.8, 0.4), checker_ambient = (0.3, 0.25, 0.1);
    edge: ambient = (0.5, 0.45, 0.35), diffuse = (0.95, 0.85, 0.6);
}

Points {
    eye = (0, 0, 0);
    centre = (0, 0, 0.604368);     // tanh(0.7): 1.4 from the eye
    above = (0, 0.3, 0.604368);
}

Lights {
    lamp: (-0.15, 0.25, 0.1), (15, 15, 15), (10, 10, 10);
}

Objects {
    Dodecahedron 0.6, #face, edges = 0.015, edge_material = #edge, at = %centre;
}

Transformations {
    vertical: hline (%centre, %above);
    @camera->Rotate(%vertical, 6.108652381980153), animate;   // 2π·35/36
    @lamp->Rotate(%vertical, 6.108652381980153), animate;     // the lamp goes along
}
