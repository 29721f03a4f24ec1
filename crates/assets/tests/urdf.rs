//! Importing a URDF written by the test itself, with an OBJ door and an STL drawer.

use behavior_assets::urdf::import_urdf;
use behavior_core::Ability;
use behavior_core::Predicate;
use behavior_sim::{Primitive, World};
use std::path::{Path, PathBuf};

fn dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("urdf")
        .join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The 8 corners and 12 triangles of a box.
fn box_mesh(min: [f32; 3], max: [f32; 3]) -> (Vec<[f32; 3]>, Vec<[usize; 3]>) {
    let v: Vec<[f32; 3]> = (0..8)
        .map(|i| {
            [
                if i & 1 == 0 { min[0] } else { max[0] },
                if i & 2 == 0 { min[1] } else { max[1] },
                if i & 4 == 0 { min[2] } else { max[2] },
            ]
        })
        .collect();
    let f = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    (v, f)
}

fn write_obj(path: &Path, (v, f): &(Vec<[f32; 3]>, Vec<[usize; 3]>)) {
    let mut text = String::from("# a door leaf\n");
    for p in v {
        text += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for t in f {
        text += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    std::fs::write(path, text).unwrap();
}

fn write_stl(path: &Path, (v, f): &(Vec<[f32; 3]>, Vec<[usize; 3]>)) {
    let mut text = String::from("solid drawer\n");
    for t in f {
        text += "facet normal 0 0 0\nouter loop\n";
        for &i in t {
            text += &format!("vertex {} {} {}\n", v[i][0], v[i][1], v[i][2]);
        }
        text += "endloop\nendfacet\n";
    }
    text += "endsolid drawer\n";
    std::fs::write(path, text).unwrap();
}

const URDF: &str = r#"<?xml version="1.0"?>
<robot name="nightstand">
  <link name="body">
    <collision><origin xyz="0 0 0.3"/><geometry><box size="0.5 0.4 0.6"/></geometry></collision>
  </link>
  <link name="knob_plate">
    <collision><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
  </link>
  <link name="door">
    <visual><geometry><mesh filename="meshes/door.obj"/></geometry></visual>
  </link>
  <link name="drawer">
    <collision><geometry><mesh filename="meshes/drawer.stl"/></geometry></collision>
  </link>
  <joint name="plate" type="fixed"><parent link="body"/><child link="knob_plate"/><origin xyz="0 0 0.61"/></joint>
  <joint name="door_hinge" type="revolute"><parent link="body"/><child link="door"/>
    <origin xyz="-0.25 -0.21 0"/><axis xyz="0 0 -1"/><limit lower="0" upper="1.5"/></joint>
  <joint name="drawer_slide" type="prismatic"><parent link="body"/><child link="drawer"/>
    <origin xyz="0 0 0.62"/><axis xyz="0 -1 0"/><limit lower="0" upper="0.3"/></joint>
</robot>
"#;

#[test]
fn a_urdf_with_obj_and_stl_meshes_becomes_an_articulated_object() {
    let d = dir("nightstand");
    std::fs::create_dir_all(d.join("meshes")).unwrap();
    // The door leaf in its link's frame (the hinge at the origin), the drawer a small box.
    write_obj(
        &d.join("meshes/door.obj"),
        &box_mesh([0.0, -0.02, 0.0], [0.5, 0.0, 0.6]),
    );
    write_stl(
        &d.join("meshes/drawer.stl"),
        &box_mesh([-0.2, -0.15, 0.0], [0.2, 0.15, 0.1]),
    );
    std::fs::write(d.join("nightstand.urdf"), URDF).unwrap();

    let mut spec = import_urdf(&d.join("nightstand.urdf"), "nightstand_1", "cabinet.n.01").unwrap();
    assert_eq!(
        spec.parts.len(),
        2,
        "the body's box and the fixed plate's cylinder"
    );
    assert!(matches!(
        spec.parts[1].primitive,
        Primitive::Cylinder { .. }
    ));
    assert_eq!(spec.links.len(), 2);
    let door = spec.links.iter().find(|l| l.name == "door_hinge").unwrap();
    assert!(!door.parts.is_empty());
    assert!(
        door.parts
            .iter()
            .all(|p| matches!(p.primitive, Primitive::ConvexHull { .. })),
        "V-HACD parts"
    );
    let drawer = spec
        .links
        .iter()
        .find(|l| l.name == "drawer_slide")
        .unwrap();
    assert_eq!(drawer.parts.len(), 1, "a collision mesh is its convex hull");
    assert_eq!(drawer.joint.limits, Some([0.0, 0.3]));

    spec.body = behavior_sim::BodyKind::Fixed;
    spec = spec.ability(Ability::Openable, &[]);
    let mut world = World::default();
    let id = world.add(spec).unwrap();
    for _ in 0..10 {
        world.step();
    }
    assert!(!world.state(id, Predicate::Open));
    world.set_joint_position(id, 1, 0.25).unwrap();
    assert!((world.core().joint_position(id, 1) - 0.25).abs() < 1e-4);
    assert!(world.state(id, Predicate::Open));
    world.set_state(id, Predicate::Open, false).unwrap();
    assert!(!world.state(id, Predicate::Open));
    let aabb = world.core().aabb(id);
    assert!(aabb.maxs.z > 0.6 && aabb.mins.x < -0.24, "{aabb:?}");
}

#[test]
fn bad_urdf_files_are_clear_errors() {
    let d = dir("bad");
    let check = |file: &str, text: &str, expected: &str| {
        let path = d.join(file);
        std::fs::write(&path, text).unwrap();
        let err = import_urdf(&path, "x", "cabinet.n.01")
            .unwrap_err()
            .to_string();
        assert!(err.contains(expected), "{err}");
    };
    check("xml.urdf", "<robot><link", "not valid XML");
    check(
        "two_roots.urdf",
        r#"<robot name="r"><link name="a"><collision><geometry><sphere radius="1"/></geometry></collision></link><link name="b"/></robot>"#,
        "expected one root link, found 2",
    );
    check(
        "limits.urdf",
        r#"<robot name="r"><link name="a"><collision><geometry><sphere radius="1"/></geometry></collision></link><link name="b"/>
           <joint name="j" type="revolute"><parent link="a"/><child link="b"/><limit lower="-1" upper="1"/></joint></robot>"#,
        "limits must run from 0",
    );
    check(
        "mesh.urdf",
        r#"<robot name="r"><link name="a"><collision><geometry><mesh filename="nowhere.obj"/></geometry></collision></link></robot>"#,
        "nowhere.obj",
    );
    check(
        "box.urdf",
        r#"<robot name="r"><link name="a"><collision><geometry><box size="1 -"/></geometry></collision></link></robot>"#,
        "is not three numbers",
    );
}
