use dynamics_codegen::front::load;
use dynamics_codegen::front::simplify::given::Defaults;
use dynamics_codegen::model::JointEnvelope;

const ROBOT: &str = "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
                     [[joints]]\ntype = \"prismatic\"\nmass = 1\n";

/// TOML and JSON give the same request, each key placed at its value.
#[test]
fn the_table_with_its_positions() {
    let toml = format!("{ROBOT}\n[simplify]\ntolerance = [0.5, 2]\nqd_max = 3\n");
    let loaded = load("a.toml", &toml).expect("toml");
    let given = loaded.simplify.expect("simplify");
    assert_eq!(given.at, (9, 1));
    assert_eq!(given.keys[0], ("tolerance", vec![0.5, 2.0], (10, 13)));
    assert_eq!(given.keys[1], ("qd_max", vec![3.0], (11, 10)));
    let json = "{\"gravity\": [0, 0, -9.81], \"joints\": [{\"type\": \"revolute\", \"mass\": 1}],\n \"simplify\": {\"tolerance\": 0.5,\n  \"q_min\": [-1]}}";
    let given = load("a.json", json)
        .expect("json")
        .simplify
        .expect("simplify");
    assert_eq!(given.at, (2, 14));
    assert_eq!(given.keys[0], ("tolerance", vec![0.5], (2, 28)));
    assert_eq!(given.keys[1], ("q_min", vec![-1.0], (3, 12)));
    let defaults = [JointEnvelope {
        lower: -1.0,
        upper: 1.0,
        speed: 2.0,
        acceleration: 5.0,
    }];
    let request = given
        .resolve(&Defaults {
            joints: defaults.to_vec(),
            rated: None,
            coordinates: false,
        })
        .expect("resolves");
    assert_eq!(request.tolerance, [0.5]);
    assert_eq!(request.envelope.joints[0].lower, -1.0);
}

/// An unknown key is an error at its line; a list of the wrong length at its key's.
#[test]
fn mistakes_at_their_positions() {
    let toml = format!("{ROBOT}\n[simplify]\ntolerance = 1\nq_mni = 3\n");
    let e = load("a.toml", &toml).err().expect("an error");
    assert_eq!(e.line, Some(11), "{e}");
    assert!(e.message.contains("unknown field `q_mni`"), "{e}");
    let toml = format!("{ROBOT}\n[simplify]\ntolerance = 1\nqd_max = [1, 2, 3]\n");
    let given = load("a.toml", &toml)
        .expect("toml")
        .simplify
        .expect("simplify");
    let defaults = [JointEnvelope {
        lower: -1.0,
        upper: 1.0,
        speed: 2.0,
        acceleration: 5.0,
    }; 2];
    let Err(problems) = given.resolve(&Defaults {
        joints: defaults.to_vec(),
        rated: None,
        coordinates: false,
    }) else {
        panic!("a list of three for two joints resolved")
    };
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].0, (11, 10));
    assert!(
        problems[0]
            .1
            .contains("`qd_max` takes one number for every joint or one per joint (2), found 3"),
        "{problems:?}"
    );
}
