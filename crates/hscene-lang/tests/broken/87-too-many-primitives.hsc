// a few bytes of text asking for gigabytes: 41511 cubes with their faces and edges pass the primitive cap, refused before anything is built
// expect: HSC0601
BRDFs   { stone: diffuse = (0.7, 0.7, 0.7); }
Lights  { (0, 0, 0.3), (1, 1, 1), (1, 1, 1); }
Objects { Tessellation435 7, #stone, edges = 0.01; }
