// lint: an animated transformation, but the scene has no `frames`
// expect: HSC1008
Points  { o = (0, 0, 0); z = (0, 0, 0.2); c = (0, 0, 0.1); }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects { ball: Sphere %c, 0.05, #1; }
Transformations {
    forward: hline (%o, %z);
    @ball->Translate(%forward), animate;
}
