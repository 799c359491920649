// Showcase: two rows of spheres along two geodesics of a checkered floor,
// 0.6 apart where they start, each sphere 0.35 further than the last. In
// hyperbolic space the rows diverge exponentially (they are not parallel
// in the Euclidean sense: the gap between them grows like cosh of the
// distance travelled) and the spheres shrink towards the absolute; fog of
// distance 3 turns the depth into a cue the eye can read. A spherical
// area light above the eye casts soft shadows on the floor.
// The sphere centres were computed on the hyperboloid: the floor is the
// h-plane 0.35 below the eye, the rows are the geodesics of the floor 0.3
// to either side of the view axis, and each centre is 0.12 above the
// floor. The floor's horizon lies 19 degrees below the eye's horizontal:
// an h-plane at distance 0.35 reaches the absolute at the angle of
// parallelism, 2 atan(exp(-0.35)) = 70.6 degrees, from straight down.
// Rendered at 1200x800, 4 samples per pixel, sRGB (the default).
Globals {
    resolution = (1200, 800);
    fov = 100;
    to = (0, -0.08, 0.3);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 1;
    samples = 4;
    fog_color = (0.75, 0.72, 0.68);
    fog_distance = 3;
}

BRDFs {
    floor: ambient = (0.2, 0.2, 0.2), diffuse = (0.8, 0.8, 0.78), specular = (0, 0, 0),
           checker = 0.25, checker_diffuse = (0.25, 0.25, 0.28), checker_ambient = (0.08, 0.08, 0.09);
    gold:  ambient = (0.3, 0.22, 0.05), diffuse = (0.9, 0.65, 0.15), specular = (0.9, 0.9, 0.8),
           shininess = 80, alpha = 0.25;
    jade:  ambient = (0.05, 0.22, 0.15), diffuse = (0.15, 0.7, 0.45), specular = (0.6, 0.6, 0.6),
           shininess = 40;
}

Points {
    f1 = (0.000000000, -0.173235158, 0.000000000);
    f2 = (0.445394387, -0.208891178, 0.000000000);
    f3 = (0.000000000, -0.208891178, 0.445394387);
    lamp = (0, 0.15, 0.2);
    r0 = (0.150827659, -0.124847909, 0.144285948);
    r1 = (0.161153154, -0.142531784, 0.302529651);
    r2 = (0.176452380, -0.168733876, 0.441300971);
    r3 = (0.193758327, -0.198372764, 0.556137330);
    r4 = (0.210598430, -0.227213827, 0.646904940);
    r5 = (0.225457465, -0.252662031, 0.716229524);
    r6 = (0.237718495, -0.273660782, 0.767888748);
    r7 = (0.247373568, -0.290196463, 0.805725872);
    r8 = (0.254730957, -0.302797034, 0.833110760);
    r9 = (0.260209374, -0.312179599, 0.852768885);
    r10 = (0.264222814, -0.319053184, 0.866800966);
    r11 = (0.267129496, -0.324031289, 0.876778205);
    r12 = (0.269217678, -0.327607598, 0.883853208);
    r13 = (0.270709327, -0.330162257, 0.888860790);
    l0 = (-0.150827659, -0.124847909, 0.144285948);
    l1 = (-0.161153154, -0.142531784, 0.302529651);
    l2 = (-0.176452380, -0.168733876, 0.441300971);
    l3 = (-0.193758327, -0.198372764, 0.556137330);
    l4 = (-0.210598430, -0.227213827, 0.646904940);
    l5 = (-0.225457465, -0.252662031, 0.716229524);
    l6 = (-0.237718495, -0.273660782, 0.767888748);
    l7 = (-0.247373568, -0.290196463, 0.805725872);
    l8 = (-0.254730957, -0.302797034, 0.833110760);
    l9 = (-0.260209374, -0.312179599, 0.852768885);
    l10 = (-0.264222814, -0.319053184, 0.866800966);
    l11 = (-0.267129496, -0.324031289, 0.876778205);
    l12 = (-0.269217678, -0.327607598, 0.883853208);
    l13 = (-0.270709327, -0.330162257, 0.888860790);
}

Lights {
    %lamp, (1, 0.97, 0.9), (0.8, 0.8, 0.8), irradiance_at = 0.8, radius = 0.08, samples = 12;
}

Objects {
    Plane %f1, %f2, %f3, #floor;
    Sphere %r0, 0.12, #gold;
    Sphere %r1, 0.12, #jade;
    Sphere %r2, 0.12, #gold;
    Sphere %r3, 0.12, #jade;
    Sphere %r4, 0.12, #gold;
    Sphere %r5, 0.12, #jade;
    Sphere %r6, 0.12, #gold;
    Sphere %r7, 0.12, #jade;
    Sphere %r8, 0.12, #gold;
    Sphere %r9, 0.12, #jade;
    Sphere %r10, 0.12, #gold;
    Sphere %r11, 0.12, #jade;
    Sphere %r12, 0.12, #gold;
    Sphere %r13, 0.12, #jade;
    Sphere %l0, 0.12, #gold;
    Sphere %l1, 0.12, #jade;
    Sphere %l2, 0.12, #gold;
    Sphere %l3, 0.12, #jade;
    Sphere %l4, 0.12, #gold;
    Sphere %l5, 0.12, #jade;
    Sphere %l6, 0.12, #gold;
    Sphere %l7, 0.12, #jade;
    Sphere %l8, 0.12, #gold;
    Sphere %l9, 0.12, #jade;
    Sphere %l10, 0.12, #gold;
    Sphere %l11, 0.12, #jade;
    Sphere %l12, 0.12, #gold;
    Sphere %l13, 0.12, #jade;
}
