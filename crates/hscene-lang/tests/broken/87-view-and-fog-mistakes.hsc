// settings: `fov` beside `window_size`, and a fog distance of zero (the
// fog colour beside it is not linted as ineffective: that would cascade)
// expect: HSC0112 HSC0403
Globals {
    resolution = (400, 300);
    window_size = (0.15, 0.1125);
    fov = 60;
    fog_distance = 0;
    fog_color = (0.5, 0.6, 0.7);
}

BRDFs { diffuse = (1, 1, 1); }
Points { (0, 0, 0.3); }
Objects { Sphere %1, 0.05, #1; }
