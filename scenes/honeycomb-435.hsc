// The order-5 cubic honeycomb {4,3,5} (thesis Fig. 36): regular h-cubes with
// 72-degree dihedral angles, five around every edge, filling hyperbolic
// space. The eye sits at the centre of the middle cell; its 36 nearest
// neighbours (depth 2) are drawn as wireframes, the near ones translucent.
Globals {
    resolution = (640, 640);
    window_size = (0.2, 0.2);
    to = (0, 0, 0.1);
    background = (0, 0, 0);
    ambient = (0.25, 0.25, 0.25);
    recursion_depth = 1;
}

BRDFs {
    edge: ambient = (0.35, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45),
          specular = (1, 1, 1), shininess = 50;
}

Points {
    o = (0, 0, 0);
    tilt = (0.1, 0.1, 0);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities above 1.
Lights {
    (0, 0, 0), (6, 6, 6), (4, 4, 4);
}

Objects {
    cells: Tessellation435 2, #edge, wireframe = 0.025;
}

Transformations {
    // Turn the honeycomb so that no edge points straight at the eye.
    axis: hline (%o, %tilt);
    @cells->Rotate(%axis, 0.4);
}
