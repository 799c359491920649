// Thesis Fig. 30, third panel (net 3): reflection and transparency without
// refraction, recursion depth 2. A transparent h-sphere (refraction index 1,
// so rays pass straight through) stands in front of a red h-cube and a
// green h-sphere; a mirror sphere on the right and a reflecting floor plane
// add reflections. fig30-transparency-depth0.hsc and -depth1.hsc are the
// same scene at recursion depths 0 and 1 (the files differ only in
// recursion_depth).
//
// Hyperbolic property: with index 1 a transmitted ray simply continues along
// its h-line (a circular arc in the ball, a diameter from the eye), so the
// objects behind the glass are seen undistorted; reflected rays follow the
// h-lines that make the mirror angle at the hit point. What changes with
// depth: at 0 there is no secondary ray at all (the glass looks like a dull
// ball, no reflections); at 1 the transmitted ray reaches the glass's own
// back wall from inside but stops there (dimmed colour of the back wall),
// and the mirrors show one bounce; at 2 the ray leaves the glass again, so
// the cube and the green sphere appear through it.
Globals {
    resolution = (400, 300);
    window_size = (1.5, 1.125);    // hyperbolic lengths on the view h-plane
    net_type = 3;
    to = (0, 0, 0.537050);         // tanh(0.6): the view h-plane at distance 1.2
    background = (0.02, 0.02, 0.04);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 2;
}

BRDFs {
    glass:  ambient = (0.02, 0.02, 0.03), diffuse = (0.1, 0.1, 0.12),
            specular = (1, 1, 1), shininess = 80,
            alpha = 0.15, trans = 0.8, refraction = 1;
    red:    ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.2, 0.15),
            specular = (0.6, 0.6, 0.6), shininess = 30;
    green:  ambient = (0.05, 0.25, 0.1), diffuse = (0.2, 0.8, 0.3),
            specular = (0.6, 0.6, 0.6), shininess = 30;
    mirror: ambient = (0.05, 0.05, 0.06), diffuse = (0.15, 0.15, 0.2),
            specular = (1, 1, 1), shininess = 80, alpha = 0.75;
    floor:  ambient = (0.12, 0.12, 0.12), diffuse = (0.4, 0.4, 0.4),
            specular = (0.3, 0.3, 0.3), shininess = 10, alpha = 0.4;
}

Points {
    glass = (-0.008062, -0.012095, 0.461888);    // distance 1.0
    cube = (0.073478, 0.036638, 0.699101);       // distance 1.75
    green = (-0.087291, 0.006204, 0.710932);     // distance 1.8
    mirror = (0.147434, -0.048139, 0.550230);    // distance 1.3
    f1 = (-0.5, -0.15, 0.3); f2 = (0, -0.15, 0.8); f3 = (0.5, -0.15, 0.3);
    lamp = (-0.1, 0.3, 0.3);
    o = (0, 0, 0); xaxis = (0.5, 0, 0); yaxis = (0, 0.5, 0);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    %lamp, (18, 18, 18), (15, 15, 15);
    (0, 0.05, 0), (15, 15, 15), (4, 4, 4);
}

Objects {
    Sphere %glass, 0.17, #glass;
    box: Cube 0.32, #red;
    Sphere %green, 0.22, #green;
    Sphere %mirror, 0.14, #mirror;
    Plane %f1, %f2, %f3, #floor;
}

Transformations {
    // Turn the cube (built at the origin) so that three faces show, then
    // move it out to %cube.
    x: hline (%o, %xaxis);
    y: hline (%o, %yaxis);
    out: hline (%o, %cube);
    @box->Rotate(%y, -0.6);
    @box->Rotate(%x, -0.5);
    @box->Translate(%out);
}
