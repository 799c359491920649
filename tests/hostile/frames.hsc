Globals { frames = 3; resolution = (8, 8); }
Points { (0,0,0.2); }
BRDFs { diffuse = (1,0,0); }
Lights { (0,0,0.1), (1,1,1), (1,1,1); }
Objects { Sphere %1, 0.1, #1; }
