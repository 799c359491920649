// Thesis Fig. 36, second panel (net 0): five {4,3,5} cells (Cube435, the
// regular h-cube with 72° dihedral angles, circumradius ~1.2265) around one
// edge, looking straight down that edge; the construction of
// fig35-large-cubes.hsc with one more cube.
//
// Hyperbolic property: since the dihedral angle shrinks as a cube grows,
// there is one size at which it is exactly 72° = 360°/5. Five such cubes
// close up around every edge with no gap and no overlap, and the cubes
// tile hyperbolic space: the order-5 cubic honeycomb {4,3,5}.
//
// Construction: cube c0 at the origin; c1 and c2 are its mirror images in
// two adjacent faces A and B; c3 is c2 reflected in A and c4 is c1
// reflected in B. Looking along the shared edge, each cube fills a wedge
// of exactly 72°.

Globals {
    resolution = (300, 300);
    window_size = (1.044954, 1.044954);   // Euclidean, on the flat screen: 76° wide
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
    purple: ambient = (0.21, 0.12, 0.27), diffuse = (0.7, 0.4, 0.9),
        specular = (0.5, 0.5, 0.5), shininess = 30;
    edge: ambient = (0.5, 0.5, 0.5), diffuse = (0.9, 0.9, 0.9);
}

Points {
    // The cube's vertices are (+-s, +-s, +-s) with s = tanh(1.22646/2)/sqrt(3).
    // Three vertices of the face x = +s, and of the face y = +s:
    a1 = (0.31546169558955, 0.31546169558955, 0.31546169558955);
    a2 = (0.31546169558955, -0.31546169558955, 0.31546169558955);
    a3 = (0.31546169558955, 0.31546169558955, -0.31546169558955);
    b1 = (0.31546169558955, 0.31546169558955, 0.31546169558955);
    b2 = (-0.31546169558955, 0.31546169558955, 0.31546169558955);
    b3 = (0.31546169558955, 0.31546169558955, -0.31546169558955);
    // The shared edge runs from (s, s, -s) to (s, s, s); mid is its midpoint.
    mid = (0.28141112302514, 0.28141112302514, 0.00000000000000);
    // The eye: on the edge's h-line, 0.5 edge lengths beyond (s, s, -s).
    eye = (0.38032308220238, 0.38032308220238, -0.52559357289757);
    up = (0.38032308220238, 0.44549209756492, -0.52559357289757);
    lamp = (0.31823133277023, 0.44241483163453, -0.52559357289757);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9); the intensity is
// scaled to the distance (~1.294) from the lamp to the near faces.
Lights {
    %lamp, (32.137, 32.137, 32.137), (16.0685, 16.0685, 16.0685);
}

Objects {
    c0: Cube435 #red, edges = 0.01528, edge_material = #edge;
    c1: Cube435 #yellow, edges = 0.01528, edge_material = #edge;
    c2: Cube435 #green, edges = 0.01528, edge_material = #edge;
    c3: Cube435 #blue, edges = 0.01528, edge_material = #edge;
    c4: Cube435 #purple, edges = 0.01528, edge_material = #edge;
}

Transformations {
    A: hplane (%a1, %a2, %a3);   // the plane of the face x = +s
    B: hplane (%b1, %b2, %b3);   // the plane of the face y = +s
    @c1->Reflect(%A);            // the neighbour across face A
    @c2->Reflect(%B);            // the neighbour across face B
    @c3->Reflect(%B);            // c2's image in A: the next one around the edge
    @c3->Reflect(%A);
    @c4->Reflect(%A);            // c1's image in B: the next one the other way
    @c4->Reflect(%B);
}
