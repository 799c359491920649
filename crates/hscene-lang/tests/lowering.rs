use hscene_lang::compile;

fn show(c: &str) {
    let r = std::panic::catch_unwind(|| compile(c));
    println!("=== {}", c.chars().take(160).collect::<String>());
    match r {
        Err(_) => println!("  PANIC"),
        Ok(r) => {
            println!(" scene={}", r.scene.is_some());
            for d in &r.diagnostics {
                println!("  {} {:?} {:?} [{}] {:?} help={:?}", d.code, d.severity, d.message, &c[d.span.start..d.span.end], d.span, d.help);
            }
            if let Some(s) = &r.scene {
                for p in &s.points { println!("  pt {:?}", p); }
                println!("  cam {:?}", s.camera);
            }
        }
    }
}

#[test]
fn probe() {
    let tr = "%2->Translate(%1); ".repeat(30);
    let cases: Vec<String> = vec![
        format!("Points {{ (0,0,-0.9999999); (0,0,0.9999999); }} Transformations {{ hline(%1,%2); {tr} }}"),
        "Points { (0,0,0); (0,0,0.999999); } Transformations { hline(%1,%2); %2->Translate(%1); }".into(),
        "Globals { from = (0,0,0.1); }".into(),
        "Points { (0.28,0.96,0); } BRDFs { diffuse=(1,1,1); } Objects { Sphere %1, 0.1, #1; }".into(),
        "Points { (0.6,0.8,0); } BRDFs { diffuse=(1,1,1); } Objects { Sphere %1, 0.1, #1; }".into(),
        "Points { (0.1,0,0.3); (0,0.1,0.3); (-0.1,0,0.3); (0,-0.1,0.35); } BRDFs { diffuse=(1,1,1); } Objects { Polygon (%1,%2,%3,%4), #1; }".into(),
        "Points { (0.1,0,0); (0,0.1,0); (-0.1,0,0); (0,-0.1,0.05); } BRDFs { diffuse=(1,1,1); } Objects { Polygon (%1,%2,%3,%4), #1; }".into(),
        "Points { (0.1,0,0.3); (0,0.1,0.3); (-0.1,0,0.3); (0,-0.1,0.3); } BRDFs { diffuse=(1,1,1); } Objects { Polygon (%1,%3,%2,%4), #1; }".into(),
        "Points { (0.1,0.1,0.3); (-0.1,0.1,0.3); (-0.1,-0.1,0.3); (0.1,-0.1,0.3); (0, 0.02, 0.3) } BRDFs { diffuse=(1,1,1); } Objects { Polygon (%1,%2,%5,%3,%4), #1; }".into(),
        "Points { (0,0,0); (0,0,0); } Transformations { hline (%1,%2); }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Sphere (0,0,0.3), 1000, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Sphere (0,0,0.3), 1e300, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Dodecahedron 40, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Sphere (0,0,0.3), -0.05, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Sphere 0.05, (0,0,0.3), #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Sphere (0,0,0.3), #1; }".into(),
        "Points { (0,0,0.3); } Transformations { hline(%1,%1); }".into(),
        "Points { (0,0,0.3); (0,0,0.2); } Transformations { %1->Rotate(%1, 0.5); }".into(),
        "Points { (0,0,0.3); (0,0,0.2); } Transformations { hline(%1,%2); %1->Rotate(%1); }".into(),
        "Globals { resolution = (0,600); }".into(),
        "Globals { resolution = (-1,600); }".into(),
        "Globals { net_type = 7; }".into(),
        "Globals { net_type = -0; }".into(),
        "Globals { recursion_depth = -1; }".into(),
        "Globals { to = (0,0,0.3); up = (0,0,0.5); }".into(),
        "Globals { to = (0,0,0.3); up = (0,0,-0.5); }".into(),
        "Points { (0,0,0.3); } Globals { to = %1; up = %1; }".into(),
        "Points { (0,0,0.3); } Objects { Sphere %1, 0.1, #1; }".into(),
        "BRDFs { diffuse = (1,1,1); } Objects { Sphere (0,0,0.3), 0.1, %1; }".into(),
        "BRDFs { diffuse = (1,1,1), colour = (1,0,0); }".into(),
        "BRDFs { glass: diffuse = (1,1,1); glass: diffuse = (1,1,1); }".into(),
        "Points { eye = (0,0,0); target = (0,0,0.3); (0.1,0,0.3); } Globals { from = %eye; to = %target; up = (0,0.1,0); }".into(),
        "Points { (0,0,0); (0.1,0,0.3); } BRDFs { diffuse = (1,1,1); } Objects { Polygon (%1, %2, (0.2,0.3,0.1)), #1; Polygon (%1, %2), #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Lights { (0,0,0.3), (1,1,1), (1,1,1); } Objects { Dodecahedron 0.5, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Lights { (0,0,0.01), (1,1,1), (1,1,1); } Objects { Dodecahedron 0.5, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Globals { from = (0,0,0.9); to = (0,0,0.95); } Objects { Dodecahedron 0.5, #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Globals { from = (0,0,0.9); to = (0,0,0.95); } Objects { Polygon ((0.1,0,0), (0,0.1,0), (-0.1,0,0)), #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Polygon ((0.1,0,-0.3), (0,0.1,-0.3), (-0.1,0,-0.3)), #1; }".into(),
        "BRDFs { diffuse=(1,1,1); } Objects { Polygon ((0.1,0,0.3), (0,0.1,0.3), (-0.1,0,0.3)), #1; }".into(),
    ];
    for c in &cases { show(c); }
}
