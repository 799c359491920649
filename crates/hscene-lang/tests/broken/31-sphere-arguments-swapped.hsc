// type: the centre and the radius of a sphere are swapped
// expect: HSC0108
Globals {
    resolution = (400, 300);
    window_size = (0.15, 0.1125);
    to = (0, 0, 0.1);
    background = (0.02, 0.02, 0.05);
}

BRDFs {
    red: ambient = (0.2, 0.05, 0.05), diffuse = (0.8, 0.2, 0.2),
         specular = (0.5, 0.5, 0.5), shininess = 40;
    glass: diffuse = (0.1, 0.1, 0.1), specular = (1, 1, 1),
           alpha = 0.1, trans = 0.8, refraction = 1.15;
}

Points {
    lamp = (0, 0.2, 0.1);
    (0, 0, 0.3);
    (0.1, 0, 0.3);
}

Lights {
    %lamp, (0.5, 0.5, 0.5), (1, 1, 1);
}

Objects {
    Sphere 0.05, %2, #red;
    Sphere %3, 0.03, #glass;
}

Transformations {
    hline (%2, %3);
    %3->Rotate(%1, 0.5);
}
