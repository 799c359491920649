// Thesis Fig. 33, second panel (net 2): the scene of fig33-original.hsc —
// a wireframe-edged octahedron, three spheres and an h-cylinder — with the
// observer, every object AND every light moved by one and the same
// h-translation, by distance 1.53 along the h-line from the origin towards
// (0.45, 0.3, -0.35).
//
// Hyperbolic property: isometries preserve everything the renderer uses
// (distances, angles, the attenuation 1/(4π sinh² r)), and every pixel net
// is defined in the camera's canonical frame. So the image is the same as
// fig33-original.hsc, pixel for pixel up to rounding, although in the ball
// every object has moved off to one side, shrunk and changed shape (the
// Euclidean picture of the scene is not preserved, only the hyperbolic one).
// The thesis moved the objects and the observer but not the lights, so its
// two images differed in lighting; here the lights move too.
Globals {
    resolution = (400, 300);
    window_size = (0.9, 0.675);    // Euclidean, in the great disk of the view plane
    net_type = 2;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 1;
}

BRDFs {
    face:  ambient = (0.15, 0.2, 0.35), diffuse = (0.3, 0.5, 0.9),
           specular = (0.8, 0.8, 0.8), shininess = 40;
    edge:  ambient = (0.5, 0.5, 0.5), diffuse = (0.9, 0.9, 0.85);
    red:   ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.2, 0.15),
           specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    green: ambient = (0.05, 0.25, 0.1), diffuse = (0.2, 0.8, 0.3),
           specular = (0.8, 0.8, 0.8), shininess = 40, alpha = 0.3;
    gold:  ambient = (0.3, 0.22, 0.08), diffuse = (0.85, 0.65, 0.25),
           specular = (1, 1, 1), shininess = 60;
}

Points {
    o = (0, 0, 0);
    away = (0.45, 0.3, -0.35);               // the translation: o -> away
    centre = (0, 0, 0.462117);               // distance 1 in front of the eye
    east = (0.153945, 0, 0.476159);          // 0.4 from the centre
    west = (-0.153945, 0, 0.476159);
    up = (0, 0.153945, 0.476159);
    c1 = (-0.3, -0.2, 0.5); c2 = (0.3, -0.1, 0.5);   // the cylinder's h-line
    lamp = (-0.15, 0.3, 0.15);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    lamp: %lamp, (12, 12, 12), (10, 10, 10);
    fill: (0.05, 0, 0), (6, 6, 6), (2, 2, 2);
}

Objects {
    octa: Octahedron 0.2, #face, edges = 0.01, edge_material = #edge, at = %centre;
    s1: Sphere %east, 0.09, #red;
    s2: Sphere %west, 0.09, #green;
    s3: Sphere %up, 0.06, #gold;
    tube: Cylinder %c1, %c2, 0.03, #gold;
}

Transformations {
    move: hline (%o, %away);
    @camera->Translate(%move);
    @lamp->Translate(%move);
    @fill->Translate(%move);
    @octa->Translate(%move);
    @s1->Translate(%move);
    @s2->Translate(%move);
    @s3->Translate(%move);
    @tube->Translate(%move);
}
