// A scene in Seifert-Weber space with what cannot be placed there (an
// unbounded plane, an area light) and what is folded in (a ball and a
// light outside the domain).
// expect: HSC1013 HSC0314
Globals { space = seifert_weber; domain = 0.03, #1; to = (0, 0, 0.3); }
BRDFs { diffuse = (0.8, 0.6, 0.2); }
Lights {
    (0, 0.85, 0), (1, 1, 1), (0, 0, 0);
    (0, 0, 0.1), (1, 1, 1), (0, 0, 0), radius = 0.05;
}
Objects {
    Plane (0.2, 0, 0), (0.2, 0.1, 0), (0.2, 0, 0.1), #1;
    Sphere (0.8, 0, 0), 0.05, #1;
}
