// Appendix A with alpha = 1, trans = 1 and recursion_depth = 64: every
// bounce doubles the rays, and the contribution never falls. The ray
// budget must end it, and the render must say so.
Globals {
    recursion_depth = 64;
    resolution = (24,24);
    window_size = (0.15,0.15);
    net_type = 0;
    to = (0,0,0.1);
    background = (0,0,0);
    ambient = (0.1,0.1,0.1);
}

BRDFs {
    ambient = (0.4,0.8,0.4),
    diffuse = (0.4,0.8,0.4),
    specular = (0.7,0.7,0.7),
    alpha = 1,
    trans = 1,
    shininess = 50,
    refraction = 1;

    ambient = (0.8,0.5,0.3),
    diffuse = (0.8,0.5,0.3),
    specular = (0.7,0.7,0.7),
    alpha = 1,
    trans = 1,
    shininess = 50,
    refraction = 2.5;
}

Points {
    (0,0,0);
    (0,0,0.16);
    (0.1,0,0);
    (0.07071067811865,0.07071067811865,0);
    (0,0.1,0);
    (-0.07071067811865,0.07071067811865,0);
    (-0.1,0,0);
    (-0.07071067811865,-0.07071067811865,0);
    (0,-0.1,0);
    (0.07071067811865,-0.07071067811865,0);
    (0,0,-0.1);
    (0,0,0.1);
}

Lights {
    %1, (0.35,0.35,0.35), (0.7,0.7,0.7);
    %4, (0.35,0.35,0.35), (0.7,0.7,0.7);
    %6, (0.35,0.35,0.35), (0.7,0.7,0.7);
    %7, (0.35,0.35,0.35), (0.7,0.7,0.7);
    %9, (0.35,0.35,0.35), (0.7,0.7,0.7);
}

Objects {
  Sphere %3, 0.05, #1;
  Sphere %4, 0.05, #1;
  Sphere %5, 0.05, #1;
  Sphere %6, 0.05, #1;
  Sphere %7, 0.05, #1;
  Sphere %8, 0.05, #1;
  Sphere %9, 0.05, #1;
  Sphere %10, 0.05, #1;
  Sphere %11, 0.05, #1;
  Sphere %12, 0.05, #1;
  Dodecahedron 0.045, #2;
}

Transformations {
  hline (%1,%2);
  hline (%1,%5);

  %1->Rotate(%2,-0.7);
  %2->Rotate(%2,-0.7);
  %3->Rotate(%2,-0.7);
  %4->Rotate(%2,-0.7);
  %5->Rotate(%2,-0.7);
  %6->Rotate(%2,-0.7);
  %7->Rotate(%2,-0.7);
  %8->Rotate(%2,-0.7);
  %9->Rotate(%2,-0.7);
  %10->Rotate(%2,-0.7);

  %1->Translate(%1);
  %2->Translate(%1);
  %3->Translate(%1);
  %4->Translate(%1);
  %5->Translate(%1);
  %6->Translate(%1);
  %7->Translate(%1);
  %8->Translate(%1);
  %9->Translate(%1);
  %10->Translate(%1);
  %11->Translate(%1);
}
