// Malformed meshes whose lines look like /etc/passwd: never echoed.
BRDFs { diffuse = (1,0,0); }
Lights { (0,0,0.3), (1,1,1), (1,1,1); }
Objects { Mesh "meshes/leak.ply", 0.5, #1; Mesh "meshes/leak.obj", 0.5, #1; }
