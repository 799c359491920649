// a reflection cannot be animated: it has no halfway state
// expect: HSC0312
Globals { frames = 24; }
Points  { o = (0, 0, 0); x = (0.1, 0, 0); y = (0, 0.1, 0); p = (0, 0, -0.3); }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { Sphere %p, 0.05, #1; }
Transformations {
    floor: hplane (%o, %x, %y);
    %p->Reflect(%floor), animate;
}
