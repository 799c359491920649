// a BOM before the first line
Points { (0,0,0.2); }
BRDFs { diffuse = (1,0,0); }
Objects { Sphere %1, 0.1, #1; }
