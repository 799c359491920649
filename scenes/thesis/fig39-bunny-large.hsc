// Thesis Fig. 39 (net 2): the Stanford bunny after scaling: the farthest vertex 4 from the centre,
// the centre moved back to 4.5 from the eye so that the eye stays outside.
// The files fig39-bunny-small.hsc and fig39-bunny-large.hsc differ only in
// the mesh size and the distance of its centre.
//
// Hyperbolic property: "what the hyperbolic bunny would have to go through
// to be called ideal". The mesh is laid out in geodesic polar coordinates
// about its centre (docs/language.md, "Mesh"), so its size is the
// hyperbolic distance from the centre to its farthest vertex. Seen from the
// eye, the view h-plane through the bunny's centre is shown whole by net 2
// as a Poincaré disk. The small bunny looks like a bunny; scaled by 6.7,
// its body wraps almost the whole view, its ears and feet run out towards the
// absolute, and its faces near the rim shrink to nothing: with ever larger
// size the vertices become ideal points and the bunny an ideal polyhedron.
Globals {
    resolution = (300, 300);
    window_size = (2, 2);          // Euclidean, in the great disk: the whole view h-plane
    net_type = 2;
    to = %centre;
    background = (0.02, 0.02, 0.05);
    ambient = (0.3, 0.3, 0.3);
    recursion_depth = 0;
}

BRDFs {
    clay: ambient = (0.3, 0.24, 0.18), diffuse = (0.85, 0.68, 0.5),
          specular = (0.4, 0.4, 0.4), shininess = 30;
}

Points {
    centre = (0, 0, 0.978026);     // tanh(2.25): distance 4.5 from the eye
    lamp = (0, 0.02, 0.848);       // 2.5 from the eye, just above the line of sight
}

// Light falls off as 1 / (4 pi sinh^2 r) (thesis Eq. 9).
Lights {
    %lamp, (60, 60, 60), (20, 20, 20);
}

Objects {
    bunny: Mesh "../meshes/bunny.ply", 4, #clay, at = %centre;
}
