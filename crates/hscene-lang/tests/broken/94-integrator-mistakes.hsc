// integrator mistakes: an unknown integrator, a number for a name, and the path integrator with a material that relies on ambient light
// expect: HSC0403 HSC0108 HSC1010
Globals { integrator = photon; }
Globals { integrator = 2; }
Globals { integrator = path; ambient = (0.2, 0.2, 0.2); }
BRDFs   { wall: ambient = (0.3, 0.3, 0.3), diffuse = (0.8, 0.8, 0.8); }
Lights  { (0, 0.3, 0), (1, 1, 1), (1, 1, 1); }
Objects { Sphere (0, 0, 0.4), 0.1, #wall; }
