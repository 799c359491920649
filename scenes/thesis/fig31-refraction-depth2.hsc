// Thesis Fig. 31, right panel (net 3): refraction. A semi-transparent
// h-dodecahedron with refraction index 1.15 stands in front of a wireframe
// h-icosahedron, at recursion depth 2. The left panel, the same scene at
// depth 1, is fig31-refraction-depth1.hsc (the files differ only in
// recursion_depth).
//
// Hyperbolic property: Snell's law holds in the tangent space at the hit
// point, and the model is conformal, so the Euclidean angles in the ball
// are the hyperbolic ones: a ray bends towards the normal on entering and
// away from it on leaving, and continues along a new h-line. Inside the
// solid, rays that meet a face at more than the critical angle
// arcsin(1 / 1.15) ≈ 60.4° are totally reflected and never get out: parts
// of the icosahedron (near the dodecahedron's rim) disappear although the
// dodecahedron is transparent. At depth 1 the refracted ray only reaches
// the dodecahedron's back faces from inside and stops, so the icosahedron
// cannot be seen through it at all; at depth 2 the ray gets out again and
// shows the icosahedron, displaced and cut up by the faces like a prism.
Globals {
    resolution = (400, 300);
    window_size = (0.9, 0.675);     // hyperbolic lengths on the view h-plane
    net_type = 3;
    to = (0, 0, 0.462117);         // tanh(0.5): the view h-plane at distance 1
    background = (0.02, 0.02, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 2;
}

BRDFs {
    glass: ambient = (0.02, 0.03, 0.04), diffuse = (0.08, 0.12, 0.15),
           specular = (1, 1, 1), shininess = 80,
           alpha = 0.1, trans = 0.85, refraction = 1.15;
    wire:  ambient = (0.35, 0.25, 0.1), diffuse = (0.95, 0.7, 0.3),
           specular = (1, 1, 1), shininess = 50;
}

Points {
    dodeca = (0, 0, 0.462117);                 // distance 1 from the eye
    ico = (0.026575, 0.013284, 0.761014);      // distance 2.0, just off the axis
    lamp = (-0.2, 0.3, 0.3);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    %lamp, (20, 20, 20), (15, 15, 15);
    (0, 0.05, 0), (20, 20, 20), (5, 5, 5);
    (0.2, 0.1, 0.85), (20, 20, 20), (5, 5, 5);   // behind, lighting the icosahedron
}

Objects {
    Dodecahedron 0.25, #glass, at = %dodeca;
    Icosahedron 0.6, #wire, wireframe = 0.025, at = %ico;
}
