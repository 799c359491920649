// Thesis Fig. 36 (net 0): the order-5 cubic honeycomb {4,3,5}. Regular
// h-cubes with 72° dihedral angles (Cube435, circumradius ~1.2265), five
// around every edge, fill hyperbolic space without gaps or overlaps. The
// eye sits at the centre of one cell; the 163 cells reachable by at most
// three reflections in faces are drawn as wireframes.
//
// Hyperbolic property: the dihedral angle of a regular h-cube shrinks as
// the cube grows (fig35); at 72° five cubes close up around an edge
// (fig36-five-around-edge.hsc) and the cubes tile space, which no
// Euclidean cube can do with five per edge. Every cell is congruent to the
// one around the eye, yet the far cells look ever smaller and their edges
// crowd together: the number of cells within distance r grows like
// e^(2r), the volume of a hyperbolic ball.
Globals {
    resolution = (400, 400);
    window_size = (0.2, 0.2);    // Euclidean, on the plane z = 0.1: 90° wide
    to = (0, 0, 0.1);
    background = (0, 0, 0);
    ambient = (0.5, 0.5, 0.5);
    recursion_depth = 0;
}

BRDFs {
    edge: ambient = (0.6, 0.5, 0.3), diffuse = (0.9, 0.75, 0.45),
          specular = (1, 1, 1), shininess = 50;
}

Points {
    o = (0, 0, 0);
    tilt = (0.1, 0.1, 0);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities above 1 for a lamp at the eye.
Lights {
    (0, 0, 0), (6, 6, 6), (4, 4, 4);
}

Objects {
    cells: Tessellation435 3, #edge, wireframe = 0.02;
}

Transformations {
    // Turn the honeycomb so that no edge points straight at the eye.
    axis: hline (%o, %tilt);
    @cells->Rotate(%axis, 0.4);
}
