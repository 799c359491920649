// Thesis Fig. 31, extra panel (net 3): where total internal reflection
// happens. The scene of fig31-refraction-depth2.hsc (a dodecahedron of
// refraction index 1.15 in front of a wireframe icosahedron, recursion
// depth 2) with a red background instead of a dark one. The files differ
// only in the background.
//
// Hyperbolic property: as in fig31-refraction-depth2.hsc, Snell's law holds
// in the tangent space at the hit point (the model is conformal). At depth
// 2 a ray that enters the front face and then leaves through a back face
// ends on the icosahedron or on the background, which is now red. Where it
// meets the back face beyond the critical angle arcsin(1 / 1.15) ≈ 60.4°,
// it is totally reflected, stays inside the glass, and the recursion ends
// there: no red, only the glass's own colour. So the grey-blue band along
// the rim of the dodecahedron is the region of total internal reflection.
Globals {
    resolution = (400, 300);
    window_size = (0.9, 0.675);     // hyperbolic lengths on the view h-plane
    net_type = 3;
    to = (0, 0, 0.462117);         // tanh(0.5): the view h-plane at distance 1
    background = (0.6, 0.12, 0.1);
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
