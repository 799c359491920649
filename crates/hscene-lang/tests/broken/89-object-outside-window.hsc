// lint: a sphere well to the right of a narrow window (in front of the
// eye, so not behind it, but no view ray of net 0 reaches it)
// expect: HSC1005
Globals {
    resolution = (400, 300);
    fov = 30;
    to = (0, 0, 0.1);
}

BRDFs { diffuse = (1, 1, 1); }
Points { (0, 0, 0.3); (0.4, 0, 0.3); }
Objects { Sphere %1, 0.05, #1; Sphere %2, 0.05, #1; }
