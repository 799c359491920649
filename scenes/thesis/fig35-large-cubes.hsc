// Thesis Fig. 35, second panel (net 0): the same construction as
// fig35-small-cubes.hsc — four regular h-cubes around one edge, looking
// straight down that edge — with cubes of circumradius 1.
//
// Hyperbolic property: a regular h-cube's dihedral angles are less than 90°
// and shrink as the cube grows (cos(angle) = 1/rho^2, rho the radius of a
// face's sphere). At circumradius 1 the angle is 76.13°, so four cubes
// around an edge fill only 304.5° and leave a 55.5° gap: cubes that tile
// Euclidean space cannot tile hyperbolic space the same way.
//
// Construction: cube c0 at the origin; c1 and c2 are its mirror images in
// two adjacent faces A and B; c3 is c2 reflected in A. Looking along the
// shared edge (a diameter from the eye), the planes through it appear as
// straight lines through the centre of the image at their true angles, so
// each cube fills a wedge equal to its dihedral angle, and the gap shows as
// an empty wedge.

Globals {
    resolution = (300, 300);
    window_size = (0.942842, 0.942842);   // Euclidean, on the flat screen: 76° wide
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
    // The cube's vertices are (+-s, +-s, +-s) with s = tanh(1/2)/sqrt(3).
    // Three vertices of the face x = +s, and of the face y = +s:
    a1 = (0.26680346514121, 0.26680346514121, 0.26680346514121);
    a2 = (0.26680346514121, -0.26680346514121, 0.26680346514121);
    a3 = (0.26680346514121, 0.26680346514121, -0.26680346514121);
    b1 = (0.26680346514121, 0.26680346514121, 0.26680346514121);
    b2 = (-0.26680346514121, 0.26680346514121, 0.26680346514121);
    b3 = (0.26680346514121, 0.26680346514121, -0.26680346514121);
    // The shared edge runs from (s, s, -s) to (s, s, s); mid is its midpoint.
    mid = (0.24659047325373, 0.24659047325373, 0.00000000000000);
    // The eye: on the edge's h-line, 0.6 edge lengths beyond (s, s, -s).
    eye = (0.32210736581492, 0.32210736581492, -0.50753824112033);
    up = (0.32210736581492, 0.40234215935133, -0.50753824112033);
    lamp = (0.26206645970024, 0.38214827192961, -0.50753824112033);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9); the intensity is
// scaled to the distance (~1.143) from the lamp to the near faces.
Lights {
    %lamp, (22.439, 22.439, 22.439), (11.2195, 11.2195, 11.2195);
}

Objects {
    c0: Cube 1, #red, edges = 0.012, edge_material = #edge;
    c1: Cube 1, #yellow, edges = 0.012, edge_material = #edge;
    c2: Cube 1, #green, edges = 0.012, edge_material = #edge;
    c3: Cube 1, #blue, edges = 0.012, edge_material = #edge;
}

Transformations {
    A: hplane (%a1, %a2, %a3);   // the plane of the face x = +s
    B: hplane (%b1, %b2, %b3);   // the plane of the face y = +s
    @c1->Reflect(%A);            // the neighbour across face A
    @c2->Reflect(%B);            // the neighbour across face B
    @c3->Reflect(%B);            // c2's image in A: the next one around the edge
    @c3->Reflect(%A);
}
