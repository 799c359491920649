// settings: a field of view wider than net 2 can show from the target's
// distance (the view h-plane subtends less than 2 atan(1/sinh d)), and a
// fog colour that does nothing without a fog distance
// expect: HSC0403 HSC1007
Globals {
    net_type = 2;
    to = (0, 0, 0.5);
    fov = 120;
    fog_color = (0.5, 0.6, 0.7);
}

BRDFs { diffuse = (1, 1, 1); }
Points { (0, 0, 0.3); }
Objects { Sphere %1, 0.05, #1; }
