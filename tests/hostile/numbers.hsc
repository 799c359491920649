// Numbers that must be reported compactly and by their real problem.
Globals { background = (1e39, 0, 0); }
Points { (0,0,0.2); (0, 0, NaN); }
BRDFs { diffuse = (1,0,0), shininess = -1e300; refraction = 1e-400, diffuse = (1,1,1); }
Objects { Sphere %1, 1e300, #1; Sphere %1, 400, #1; Sphere %1, 711, #1; }
