use hscene_lang::compile;

#[test]
fn probe() {
    let cases: &[&str] = &[
        include_str!("../../../scenes/thesis-appendix-a.hsc"),
        "",
        "Points { (0,0,1.2); }",
        "Pionts { (0,0,0); }",
        "points { (0,0,0); }",
        "Globals { resolutoin = (800,600); }",
        "Objects { sphere %1, 0.1, #1; }",
        "Transformations { %1->Rotat(%2, 0.5); }",
        "Globals { to = %1; } Points { (0,0,0.3); }",
        "Points { (1,0,0); } BRDFs { diffuse=(1,1,1); } Objects { Sphere %1, 0.1, #1; }",
        "Points { (1,0,0); } Lights { %1, (1,1,1), (1,1,1); }",
        "Globals { from = (0,0,0); to = (0,0,0); }",
        "Globals { alpha = 2; }",
        "BRDFs { alpha = 2; }",
        "Globals { net_type = 0; net_type = 2; }",
        "Points { eye = (0,0,0); eye = (0,0,0.1); }",
        "Points { (0.99999999999,0,0); } Globals { to = (0,0,0.3); up = %1; }",
        "Points { (0,0,0.3);  } Lights { %1, (1,1,1), (1,1,1); } BRDFs { diffuse=(1,1,1), trans=0; } Objects { Sphere %1, 0.2, #1; }",
        "Points { (0,0,-0.3);  } BRDFs { diffuse=(1,1,1); } Objects { Sphere %1, 0.05, #1; }",
        "Objects { Sphere %3, 0.05 #1; }",
    ];
    for c in cases {
        let r = compile(c);
        println!("=== {}\n scene={}", c.lines().next().unwrap_or(""), r.scene.is_some());
        for d in &r.diagnostics {
            println!("  {} {:?} {:?} [{}] help={:?}", d.code, d.severity, d.message, &c[d.span.start..d.span.end], d.help);
        }
    }
}
