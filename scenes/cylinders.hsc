// h-cylinders (thesis Fig. 40, "h-cylinders"): the points at a fixed
// hyperbolic distance from a whole h-line. Each is a "banana" through the
// two ideal ends of its line. A horosphere tangent to the absolute below
// serves as the floor, and the camera orbits the scene's centre.
Globals {
    resolution = (720, 540);
    window_size = (0.6, 0.45);   // Euclidean, on the view plane: about 60 degrees wide
    from = %eye;
    to = %centre;
    background = (0.02, 0.03, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 2;
}

BRDFs {
    green: ambient = (0.1, 0.3, 0.1), diffuse = (0.3, 0.8, 0.3),
           specular = (0.8, 0.8, 0.8), shininess = 40;
    blue:  ambient = (0.1, 0.15, 0.35), diffuse = (0.3, 0.45, 0.9),
           specular = (0.8, 0.8, 0.8), shininess = 40;
    gold:  ambient = (0.3, 0.25, 0.1), diffuse = (0.85, 0.7, 0.3),
           specular = (1, 1, 1), shininess = 60, alpha = 0.3;
    floor: ambient = (0.2, 0.2, 0.2), diffuse = (0.6, 0.6, 0.6), alpha = 0.2;
}

Points {
    eye = (0, 0.05, -0.1);
    centre = (0, 0, 0.35);
    above = (0, 0.2, 0.35);
    left = (-0.2, 0.1, 0.35);   right = (0.2, 0.1, 0.35);
    back = (0.1, -0.1, 0.6);    front = (-0.1, -0.1, 0.2);
    bottom = (0, -1, 0);        // ideal: the floor's centre
    ground = (0, -0.18, 0.35);
    lamp = (0.2, 0.4, 0.1);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities above 1.
Lights {
    %lamp, (5, 5, 5), (5, 5, 5);
    %eye, (2, 2, 2), (1, 1, 1);
}

Objects {
    Cylinder %left, %right, 0.03, #green;     // a horizontal line, both ways to the absolute
    Cylinder %back, %front, 0.025, #blue;     // a line crossing it in depth
    Cylinder %centre, %above, 0.02, #gold;    // the vertical through the centre
    Horosphere %bottom, %ground, #floor;
}

Transformations {
    vertical: hline (%centre, %above);
    @camera->Rotate(%vertical, 0.35);         // orbit the eye about the centre
}
