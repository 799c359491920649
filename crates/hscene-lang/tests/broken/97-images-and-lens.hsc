// image textures and the lens: a missing texture, a file that is no image, a texture that is not a file name, a turn out of range, a turn with no texture, a missing sky image, a lens of radius 0 (the focus beside it is then not judged)
// expect: HSC0503 HSC0504 HSC0108 HSC0403 HSC1007 HSC0503 HSC0403
Globals { sky = "no/such/sky.exr"; aperture = 0; focus = 2; }
BRDFs {
    a: diffuse = (1, 1, 1), texture = "no/such/file.png";
    b: diffuse = (1, 1, 1), texture = "meshes/degenerate.obj";
    c: diffuse = (1, 1, 1), texture = 3;
    d: diffuse = (1, 1, 1), texture = "meshes/no.png", texture_rotate = 400;
    e: diffuse = (1, 1, 1), texture_rotate = 10;
}
Lights  { (0, 0.5, 0), (1, 1, 1), (1, 1, 1); }
Objects {
    Sphere (0, 0, 0.4), 0.1, #a; Sphere (0.2, 0, 0.4), 0.1, #b; Sphere (-0.2, 0, 0.4), 0.1, #c;
    Sphere (0, 0.2, 0.4), 0.1, #d; Sphere (0, -0.2, 0.4), 0.1, #e;
}
