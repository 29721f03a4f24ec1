//! Importing URDFs written by the tests themselves: an OBJ door and an STL drawer on joints,
//! visual meshes and primitives kept as the object's appearance beside its collision geometry.

use behavior_assets::import_urdf;
use behavior_core::Ability;
use behavior_core::Predicate;
use behavior_sim::{ObjectSpec, Part, Primitive, VisualShape, World};
use rapier3d::math::Vector;
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

/// A hexagonal prism standing on z = 0: 12 vertices and 20 triangles.
fn hexagonal_prism(radius: f32, height: f32) -> (Vec<[f32; 3]>, Vec<[usize; 3]>) {
    let v: Vec<[f32; 3]> = [0.0, height]
        .into_iter()
        .flat_map(|z| {
            (0..6).map(move |k| {
                let a = std::f32::consts::TAU * k as f32 / 6.0;
                [radius * a.cos(), radius * a.sin(), z]
            })
        })
        .collect();
    let mut f = Vec::new();
    for k in 0..6 {
        let n = (k + 1) % 6;
        f.extend([[k, n, 6 + n], [k, 6 + n, 6 + k]]);
    }
    for k in 1..5 {
        f.push([0, k + 1, k]);
        f.push([6, 6 + k, 6 + k + 1]);
    }
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
    // The door's visual mesh is also its look, on its link (the first moving one), in the
    // object's frame: moved by the hinge's origin.
    assert_eq!(spec.meshes.len(), 1);
    let look = &spec.meshes[0];
    assert_eq!(look.link, Some(0));
    assert_eq!((look.vertices.len(), look.triangles.len()), (8, 12));
    assert!(
        look.vertices
            .iter()
            .any(|v| (*v - Vector::new(-0.25, -0.23, 0.0)).length() < 1e-6),
        "{:?}",
        look.vertices
    );
    assert_eq!(look.visual, spec.visual, "no material: the object's look");

    spec.body = behavior_sim::BodyKind::Fixed;
    spec = spec.ability(Ability::Openable, &[]);
    let mut world = World::default();
    let id = world.add(spec).unwrap();
    for _ in 0..10 {
        world.step();
    }
    assert!(!world.state(id, Predicate::Open));
    world.joints_mut().set_position(id, 1, 0.25).unwrap();
    assert!((world.joints().position(id, 1) - 0.25).abs() < 1e-4);
    assert!(world.state(id, Predicate::Open));
    world.set_state(id, Predicate::Open, false).unwrap();
    assert!(!world.state(id, Predicate::Open));
    let aabb = world.bodies().aabb(id);
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
    let missing = import_urdf(&d.join("absent.urdf"), "x", "cabinet.n.01").unwrap_err();
    assert!(
        std::error::Error::source(&missing).is_none(),
        "the cause is in the message only: {missing}"
    );
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

const CUPBOARD: &str = r#"<?xml version="1.0"?>
<robot name="cupboard">
  <material name="oak"><color rgba="0.6 0.4 0.2 1"/></material>
  <link name="body">
    <collision><origin xyz="0 0 0.3"/><geometry><box size="0.5 0.4 0.6"/></geometry></collision>
    <visual>
      <geometry><mesh filename="meshes/body.obj"/></geometry>
      <material name="red"><color rgba="1 0 0 1"/></material>
    </visual>
  </link>
  <link name="door">
    <collision><origin xyz="0.25 -0.01 0.3"/><geometry><box size="0.5 0.02 0.6"/></geometry></collision>
    <visual><geometry><mesh filename="meshes/door.obj"/></geometry><material name="oak"/></visual>
  </link>
  <joint name="door_hinge" type="revolute"><parent link="body"/><child link="door"/>
    <origin xyz="-0.25 -0.2 0"/><axis xyz="0 0 -1"/><limit lower="0" upper="1.5"/></joint>
</robot>
"#;

#[test]
fn visual_meshes_are_drawn_while_collision_keeps_its_own_geometry() {
    let d = dir("cupboard");
    std::fs::create_dir_all(d.join("meshes")).unwrap();
    // The body looks like a hexagonal prism 0.8 m tall, though it collides as a 0.6 m box.
    write_obj(&d.join("meshes/body.obj"), &hexagonal_prism(0.25, 0.8));
    write_obj(
        &d.join("meshes/door.obj"),
        &box_mesh([0.0, -0.02, 0.0], [0.5, 0.0, 0.6]),
    );
    std::fs::write(d.join("cupboard.urdf"), CUPBOARD).unwrap();
    let spec = import_urdf(&d.join("cupboard.urdf"), "cupboard_1", "cabinet.n.01").unwrap();

    // Collision as before: the collision boxes only.
    assert_eq!(spec.parts.len(), 1);
    assert!(matches!(spec.parts[0].primitive, Primitive::Box { .. }));
    assert_eq!(spec.links.len(), 1);
    assert_eq!(spec.links[0].parts.len(), 1);
    assert!(matches!(
        spec.links[0].parts[0].primitive,
        Primitive::Box { .. }
    ));

    let mut world = World::default();
    let id = world.add(spec.fixed()).unwrap();
    let parts = world.visuals().parts(id);
    assert_eq!(parts.len(), 2, "one mesh each for the body and the door");
    let VisualShape::Mesh(body) = parts[0].shape else {
        panic!("the body is drawn from its mesh: {:?}", parts[0].shape);
    };
    assert_eq!((parts[0].link, body.link), (None, None));
    assert_eq!((body.vertices.len(), body.triangles.len()), (12, 20));
    assert_eq!(parts[0].visual.color, [255, 0, 0], "its own rgba");
    let VisualShape::Mesh(door) = parts[1].shape else {
        panic!("the door is drawn from its mesh: {:?}", parts[1].shape);
    };
    assert_eq!((parts[1].link, door.link), (Some(0), Some(0)));
    assert_eq!(door.vertices.len(), 8);
    assert_eq!(parts[1].visual.color, [153, 102, 51], "the named material");
    assert!(door.vertices.contains(&Vector::new(0.25, -0.2, 0.6)));

    // The door's mesh swings with its link.
    let closed = parts[1].pose;
    world.joints_mut().set_position(id, 0, 1.2).unwrap();
    let open = world.visuals().parts(id)[1].pose;
    assert!(open.rotation.angle_between(closed.rotation) > 1.0);

    // A block dropped on the cupboard rests on the 0.6 m collision box, not on the 0.8 m look.
    let block = ObjectSpec::new(
        "block",
        "block.n.01",
        vec![Part::new(Primitive::Box {
            half_extents: Vector::splat(0.05),
        })],
    )
    .at(Vector::new(0.0, 0.05, 1.0));
    let block = world.add(block).unwrap();
    for _ in 0..180 {
        world.step();
    }
    let z = world.bodies().pose(block).translation.z;
    assert!((z - 0.65).abs() < 0.01, "the block rests at z = {z}");
}

#[test]
fn visual_primitives_become_meshes_and_unreadable_visuals_fall_back_to_collision() {
    let d = dir("looks");
    let import = |file: &str, visual: &str| {
        let text = format!(
            r#"<robot name="r"><link name="a">
                 <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
                 <visual><origin xyz="0 0 0.5"/>{visual}</visual>
               </link></robot>"#
        );
        std::fs::write(d.join(file), text).unwrap();
        import_urdf(&d.join(file), "x", "cabinet.n.01").unwrap()
    };
    let spec = import(
        "cylinder.urdf",
        r#"<geometry><cylinder radius="0.1" length="0.4"/></geometry>"#,
    );
    assert_eq!(spec.parts.len(), 1, "collision from <collision> only");
    let [look] = spec.meshes.as_slice() else {
        panic!("{:?}", spec.meshes);
    };
    assert_eq!((look.vertices.len(), look.triangles.len()), (50, 96));
    let top = look.vertices.iter().map(|v| v.z).fold(f32::MIN, f32::max);
    assert!(
        (top - 0.7).abs() < 1e-6,
        "placed by its origin: top at {top}"
    );
    assert_eq!(look.visual, spec.visual);

    let sphere = import(
        "sphere.urdf",
        r#"<geometry><sphere radius="0.1"/></geometry><material name="m"><color rgba="0 0.5 1 0.3"/></material>"#,
    );
    assert_eq!(sphere.meshes[0].visual.color, [0, 128, 255]);
    assert_eq!(sphere.meshes[0].vertices.len(), 2 + 11 * 24);

    // A COLLADA look cannot be read: the import still succeeds, drawn from its collision box.
    let dae = import(
        "dae.urdf",
        r#"<geometry><mesh filename="meshes/look.dae"/></geometry>"#,
    );
    assert!(dae.meshes.is_empty());
    assert_eq!(dae.parts.len(), 1);
}
