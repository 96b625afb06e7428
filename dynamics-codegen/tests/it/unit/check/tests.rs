use dynamics_codegen::check::{robot, LinkParameter, Problem, MAX_JOINTS};
use dynamics_codegen::model::{Convention, Joint, JointKind, Link, Pose, Robot, Value};

fn joint(mass: f64) -> Joint {
    let link = Link {
        mass: Value::from_f64(mass),
        inertia: [1.0, 1.0, 3.0, 0.0, 0.0, 0.0].map(Value::from_f64),
        ..Link::default()
    };
    Joint::dh(JointKind::Revolute, Default::default(), link)
}

fn chain(masses: &[f64]) -> Robot {
    Robot {
        name: "chain".into(),
        convention: Convention::Standard,
        gravity: Default::default(),
        joints: masses.iter().map(|m| joint(*m)).collect(),
        base: Pose::identity(),
        tool: None,
        tips: Vec::new(),
    }
}

#[test]
fn joint_count_first_then_links_base_to_tip() {
    let mut masses = vec![1.0; MAX_JOINTS + 1];
    masses[2] = -1.0;
    let problems = robot(&chain(&masses), &[]);
    // Every link breaks the triangle inequality 1 + 1 < 3; link 3's mass is negative too.
    assert_eq!(problems.len(), 2 + masses.len());
    assert_eq!(
        problems[0],
        Problem::TooManyJoints {
            count: MAX_JOINTS + 1
        }
    );
    assert!(problems[0].to_string().starts_with("17 joints; at most 16"));
    let Problem::Link { joint, problem } = &problems[3] else {
        panic!("{:?}", problems[3]);
    };
    assert_eq!((*joint, problem.parameter), (2, LinkParameter::Mass));
    assert!(problems[3]
        .to_string()
        .starts_with("joint 3: the mass is negative"));
}

#[test]
fn unchecked_inertia_is_skipped() {
    assert_eq!(robot(&chain(&[1.0, 1.0]), &[false, true]).len(), 1);
    assert!(robot(&chain(&[1.0]), &[false]).is_empty());
}
