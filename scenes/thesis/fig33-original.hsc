// Thesis Fig. 33, first panel (net 2): a wireframe-edged h-octahedron,
// three h-spheres and an h-cylinder, seen from the eye at the origin, with
// two lights. In fig33-translated.hsc the observer, the objects and the
// lights are all moved by one h-translation; the two images are the same.
//
// Hyperbolic property: see fig33-translated.hsc. This file differs from it
// only in leaving out the translations.
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

// fig33-translated.hsc adds a Transformations section that moves the camera,
// both lights and every object along the h-line from %o to %away.
