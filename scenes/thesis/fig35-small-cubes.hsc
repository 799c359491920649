// Thesis Fig. 35, first panel (net 0): four small regular h-cubes around
// one edge, seen looking straight down that edge. (Circumradius 0.1: the
// cubes are tiny compared with the curvature of the space, so they behave
// almost like Euclidean cubes: this stands in for the thesis's Euclidean
// tiling.) fig35-large-cubes.hsc is the same construction with big cubes.
//
// Hyperbolic property: the dihedral angle of a regular h-cube depends on its
// size. cos(angle) = 1/rho^2 where rho is the radius of a face's sphere; at
// circumradius 0.1 the angle is 89.81°, so four cubes around an edge fill
// 359.2° and close up to within a hair, as cubes do in Euclidean space.
//
// Construction: cube c0 at the origin; c1 and c2 are its mirror images in
// two adjacent faces A and B; c3 is c2 reflected in A. Looking along the
// shared edge (a diameter from the eye), the planes through it appear as
// straight lines through the centre of the image at their true angles, so
// each cube fills a wedge equal to its dihedral angle.

Globals {
    resolution = (300, 300);
    window_size = (0.197629, 0.197629);   // Euclidean, on the flat screen: 76° wide
    net_type = 0;
    from = %eye;
    to = %mid;
    up = %up;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    red: ambient = (0.27, 0.09, 0.07), diffuse = (0.9, 0.3, 0.25),
        specular = (0.5, 0.5, 0.5), shininess = 30;
    yellow: ambient = (0.27, 0.24, 0.09), diffuse = (0.9, 0.8, 0.3),
        specular = (0.5, 0.5, 0.5), shininess = 30;
    green: ambient = (0.09, 0.24, 0.12), diffuse = (0.3, 0.8, 0.4),
        specular = (0.5, 0.5, 0.5), shininess = 30;
    blue: ambient = (0.09, 0.15, 0.28), diffuse = (0.3, 0.5, 0.95),
        specular = (0.5, 0.5, 0.5), shininess = 30;
    edge: ambient = (0.5, 0.5, 0.5), diffuse = (0.9, 0.9, 0.9);
}

Points {
    // The cube's vertices are (+-s, +-s, +-s) with s = tanh(0.1/2)/sqrt(3).
    // Three vertices of the face x = +s, and of the face y = +s:
    a1 = (0.02884348123021, 0.02884348123021, 0.02884348123021);
    a2 = (0.02884348123021, -0.02884348123021, 0.02884348123021);
    a3 = (0.02884348123021, 0.02884348123021, -0.02884348123021);
    b1 = (0.02884348123021, 0.02884348123021, 0.02884348123021);
    b2 = (-0.02884348123021, 0.02884348123021, 0.02884348123021);
    b3 = (0.02884348123021, 0.02884348123021, -0.02884348123021);
    // The shared edge runs from (s, s, -s) to (s, s, s); mid is its midpoint.
    mid = (0.02881946505266, 0.02881946505266, 0.00000000000000);
    // The eye: on the edge's h-line, 1.7 edge lengths beyond (s, s, -s).
    eye = (0.02927969639635, 0.02927969639635, -0.12626365606561);
    up = (0.02927969639635, 0.17663112958358, -0.12626365606561);
    lamp = (0.01924257243103, 0.03931682036168, -0.12626365606561);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9); the intensity is
// scaled to the distance (~0.231) from the lamp to the near faces.
Lights {
    %lamp, (0.615, 0.615, 0.615), (0.3075, 0.3075, 0.3075);
}

Objects {
    c0: Cube 0.1, #red, edges = 0.00109, edge_material = #edge;
    c1: Cube 0.1, #yellow, edges = 0.00109, edge_material = #edge;
    c2: Cube 0.1, #green, edges = 0.00109, edge_material = #edge;
    c3: Cube 0.1, #blue, edges = 0.00109, edge_material = #edge;
}

Transformations {
    A: hplane (%a1, %a2, %a3);   // the plane of the face x = +s
    B: hplane (%b1, %b2, %b3);   // the plane of the face y = +s
    @c1->Reflect(%A);            // the neighbour across face A
    @c2->Reflect(%B);            // the neighbour across face B
    @c3->Reflect(%B);            // c2's image in A: the next one around the edge
    @c3->Reflect(%A);
}
