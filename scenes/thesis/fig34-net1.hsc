// Thesis Fig. 34, net 1: one h-dodecahedron (circumradius 0.6, its centre
// 1.4 in front of the eye, on the view h-plane) seen through pixel net 1.
// The four files fig34-net0/1/3/4.hsc differ only in net_type and
// window_size.
//
// Hyperbolic property: the pixel nets are different ways of laying a
// rectangle of pixels over the view h-plane. From the eye every h-line lies
// in a Euclidean plane through the eye, so nets that sample along straight
// lines through the view direction — net 0 (a Euclidean grid on a flat
// screen) and net 1 (a grid of hyperparallel h-lines, i.e. a Klein-model
// grid) — show the edges straight (net 0 exactly, net 1 nearly): the
// picture looks Euclidean, only the scale differs. Nets 3 and 4 sample the view h-plane by equidistant curves
// and show it as a Poincaré disk, where every h-line becomes an arc of a
// circle orthogonal to the disk's rim: the dodecahedron's edges curve.
// Net 1: the pixel (a, b) is where the h-lines perpendicular to the two
// axes at distances a and b meet, i.e. the Klein point (tanh a, tanh b).
// Pixels are evenly spaced in a and b, while h-lines are straight in
// tanh a, tanh b, so only edges perpendicular to a screen axis come out
// exactly straight; slanted ones bow slightly (far less than in nets 3
// and 4: the thesis's "looks Euclidean" holds for local scenes). Towards
// the corners the two h-lines stop meeting (tanh^2 a + tanh^2 b >= 1): the
// net does not cover the whole view h-plane, the corners are background.
Globals {
    resolution = (300, 300);
    window_size = (2.1, 2.1);      // hyperbolic lengths on the view h-plane
    net_type = 1;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    face: ambient = (0.15, 0.2, 0.35), diffuse = (0.3, 0.5, 0.9),
          specular = (0.8, 0.8, 0.8), shininess = 40;
    edge: ambient = (0.5, 0.45, 0.35), diffuse = (0.95, 0.85, 0.6),
          specular = (1, 1, 1), shininess = 50;
}

Points {
    centre = (0, 0, 0.604368);     // tanh(0.7): distance 1.4 from the eye
    o = (0, 0, 0); xaxis = (0.5, 0, 0); yaxis = (0, 0.5, 0);
    lamp = (-0.15, 0.25, 0.1);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    %lamp, (15, 15, 15), (10, 10, 10);
    (0, 0, 0), (8, 8, 8), (4, 4, 4);
}

Objects {
    dodeca: Dodecahedron 0.6, #face, edges = 0.015, edge_material = #edge;
}

Transformations {
    // Turn the dodecahedron (built at the origin) to show it at an angle,
    // then move it out to %centre.
    x: hline (%o, %xaxis);
    y: hline (%o, %yaxis);
    out: hline (%o, %centre);
    @dodeca->Rotate(%x, 0.35);
    @dodeca->Rotate(%y, 0.3);
    @dodeca->Translate(%out);
}
