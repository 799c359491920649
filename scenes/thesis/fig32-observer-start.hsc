// Thesis Fig. 32, starting position (net 3): a cube with edges at the
// scene's centre (distance 1.2 in front of the eye), four spheres around it
// in a horizontal h-plane (red east, blue west, green far, yellow near) and
// a white one on top, seen from the eye at the origin. In
// fig32-observer-rotated.hsc the observer is moved by an h-rotation about
// the vertical h-line through the centre.
//
// Hyperbolic property: see fig32-observer-rotated.hsc. This file differs
// from it only in leaving out the camera rotation.
Globals {
    resolution = (400, 300);
    window_size = (1.6, 1.2);      // hyperbolic lengths on the view h-plane
    net_type = 3;
    from = %eye;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 1;
}

BRDFs {
    box:    ambient = (0.2, 0.2, 0.25), diffuse = (0.5, 0.55, 0.7),
            specular = (0.6, 0.6, 0.6), shininess = 30;
    edge:   ambient = (0.5, 0.5, 0.5), diffuse = (0.9, 0.9, 0.9);
    red:    ambient = (0.3, 0.05, 0.05), diffuse = (0.9, 0.2, 0.15),
            specular = (0.8, 0.8, 0.8), shininess = 40;
    blue:   ambient = (0.05, 0.1, 0.3), diffuse = (0.2, 0.4, 0.95),
            specular = (0.8, 0.8, 0.8), shininess = 40;
    green:  ambient = (0.05, 0.25, 0.1), diffuse = (0.2, 0.8, 0.3),
            specular = (0.8, 0.8, 0.8), shininess = 40;
    yellow: ambient = (0.3, 0.25, 0.05), diffuse = (0.9, 0.8, 0.2),
            specular = (0.8, 0.8, 0.8), shininess = 40;
    white:  ambient = (0.3, 0.3, 0.3), diffuse = (0.9, 0.9, 0.9),
            specular = (0.8, 0.8, 0.8), shininess = 40;
}

Points {
    // The eye is 0.51 above the horizontal h-plane through the centre. It
    // has to be that high to see the cube's top face: the plane of that face
    // and the horizontal plane are ultraparallel, and at 1.2 from the axis
    // the face's plane has already risen to about 0.32 above it.
    eye = (0, 0.25, 0);
    centre = (0, 0, 0.537050);              // tanh(0.6): distance 1.2
    // Distance 0.55 from the centre in the h-plane through it orthogonal to
    // the vertical; top: 0.5 up the vertical h-line.
    east = (0.187014, 0, 0.563994);   west = (-0.187014, 0, 0.563994);
    far = (0, 0, 0.703906);           near = (0, 0, 0.314021);
    top = (0, 0.171315, 0.559583);
    lamp = (-0.2, 0.35, 0.3);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    %lamp, (15, 15, 15), (12, 12, 12);
    (0.3, 0.2, 0.75), (10, 10, 10), (6, 6, 6);
}

Objects {
    Cube 0.3, #box, edges = 0.012, edge_material = #edge, at = %centre;
    Sphere %east, 0.1, #red;
    Sphere %west, 0.1, #blue;
    Sphere %far, 0.1, #green;
    Sphere %near, 0.07, #yellow;
    Sphere %top, 0.07, #white;
}

Transformations {
    vertical: hline (%centre, %top);       // the vertical h-line through the centre
    // (fig32-observer-rotated.hsc adds: @camera->Rotate(%vertical, 1);)
}
