// Thesis Fig. 28, smoothed: fig28-bunny.hsc with `smooth = 60`, so each
// h-triangle is shaded with normals interpolated from its vertices (their
// normals averaged over the faces around them that bend by less than 60
// degrees) instead of its own flat normal. The silhouette and every hit are
// those of the flat render; only the lighting changes (docs/geometry.md,
// "Smooth meshes").
//
// Thesis Fig. 28, net 0: the Stanford bunny, a scanned model of 3674
// triangles (scenes/meshes/bunny.ply), rendered as a mesh of h-triangles.
//
// The file's Euclidean coordinates are laid out in geodesic polar
// coordinates about the bunny's centre (docs/language.md, "Mesh"): its
// farthest vertex is 0.8 from its centre, and each face becomes the
// h-triangle spanned by its vertices, with `at` moving the centre 1.5 in
// front of the eye. The thesis calls meshes impractical in the Poincaré
// ball; in the Klein model of the bunny's own frame h-triangles are
// Euclidean triangles, so a bounding-box hierarchy there makes each ray cost
// a few dozen triangle tests instead of 3674.
Globals {
    resolution = (400, 400);
    window_size = (0.5, 0.5);     // Euclidean, on the flat screen z = tanh(0.75)
    net_type = 0;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 0;
}

BRDFs {
    clay: ambient = (0.3, 0.24, 0.18), diffuse = (0.85, 0.68, 0.5),
          specular = (0.4, 0.4, 0.4), shininess = 30;
}

Points {
    centre = (0, 0, 0.635149);    // tanh(0.75): distance 1.5 from the eye
    lamp = (-0.25, 0.3, 0.45);
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9), hence the
// intensities well above 1.
Lights {
    %lamp, (30, 30, 30), (12, 12, 12);
    (0.25, -0.1, 0.2), (8, 8, 8), (2, 2, 2);
}

Objects {
    bunny: Mesh "../meshes/bunny.ply", 0.8, #clay, at = %centre, smooth = 60;
}
