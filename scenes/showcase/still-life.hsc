// Showcase: a still life with the artist's camera. On an h-plane textured
// with the {7,3} tiling (drawn in the Poincare disc, it lands on the plane as
// that exact tiling: straight edges along the plane's geodesics) stand a
// mirror ball reflecting the sky, a ball of tinted glass, a globe textured
// by latitude and longitude, and a visible spherical lamp. The lens is
// focused on the mirror ball (aperture 0.02): the globe in front and the
// far floor blur by the circle of confusion derived in docs/rendering.md.
//   hscene render scenes/showcase/still-life.hsc -o still-life.png
Globals {
    resolution = (640, 480);
    fov = 75;
    from = %eye;
    to = %target;
    ambient = (0.25, 0.25, 0.27);
    recursion_depth = 6;
    samples = 49;
    sky = ((0.25, 0.45, 0.85), (0.9, 0.85, 0.75));
    aperture = 0.025;
    focus = 1.2;
}

BRDFs {
    floor: ambient = (0.9, 0.9, 0.9), diffuse = (0.85, 0.85, 0.85),
           specular = (0.1, 0.1, 0.1), shininess = 10,
           texture = "../textures/tiling-7-3.png";
    mirror: ambient = (0.02, 0.02, 0.02), diffuse = (0.05, 0.05, 0.05),
            specular = (1, 1, 1), shininess = 200, alpha = 0.9;
    glass: ambient = (0.01, 0.01, 0.01), diffuse = (0.02, 0.02, 0.02),
           specular = (1, 1, 1), shininess = 150, trans = 0.95,
           refraction = 1.5, absorption = (0.2, 1.5, 2.5);
    globe: ambient = (0.8, 0.8, 0.8), diffuse = (0.9, 0.9, 0.9),
           specular = (0.3, 0.3, 0.3), shininess = 30,
           texture = "../textures/bands.png", texture_rotate = 30;
}

Points {
    eye = (0, -0.3, -0.25);
    target = (0, -0.41, 0.2);
    // Each ball first rests on the plane y = 0 at the origin (its centre
    // its radius up the y axis), then slides within that plane along a line
    // through the origin (an isometry that keeps the plane), and the whole
    // arrangement is lowered 0.9 onto the floor (docs/language.md, "Resting
    // an object on a plane").
    mirror_at: (0, 1, 0), distance = 0.18;
    glass_at: (0, 1, 0), distance = 0.13;
    globe_at: (0, 1, 0), distance = 0.1;
    lamp_at = (0.2, -0.18, 0.32);
}

Transformations {
    down: hline ((0, 0, 0), (0, -0.5, 0));
    to_mirror: hline ((0, 0, 0), (0, 0, 0.5));
    to_glass: hline ((0, 0, 0), (-0.4, 0, 0.25));
    to_globe: hline ((0, 0, 0), (0.4, 0, 0.1));
    %mirror_at->Translate(%to_mirror, 0.75);
    %glass_at->Translate(%to_glass, 0.7);
    %globe_at->Translate(%to_globe, 0.45);
    %mirror_at->Translate(%down, 0.9);
    %glass_at->Translate(%down, 0.9);
    %globe_at->Translate(%down, 0.9);
    @floor->Translate(%down, 0.9);
}

Lights {
    %lamp_at, (3, 2.8, 2.5), (1.5, 1.5, 1.4), irradiance_at = 0.8, radius = 0.04, samples = 4;
}

Objects {
    floor: Plane (0, 0, 0), (0.5, 0, 0), (0, 0, 0.5), #floor;
    Sphere %mirror_at, 0.18, #mirror;
    Sphere %glass_at, 0.13, #glass;
    Sphere %globe_at, 0.1, #globe;
}
