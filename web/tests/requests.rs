//! The request layer on the host: errors as JSON with the library's message and the argument's
//! name, non-finite numbers through JSON, and schemes written and read back unchanged.

use serde_json::{json, Value};
use shadow_aliasing::frame::{Aabb, Bound, Camera, FrameInput};
use shadow_aliasing::plan::candidates::candidates;
use shadow_aliasing_web::{call, scheme};

/// The camera of web/test/checks.mjs (eye (0, 10, 20) looking at (0, 0, −20)), world → eye,
/// column-major, written out by hand from its orthonormal frame.
fn view() -> Vec<f64> {
    let fwd = glam::DVec3::new(0.0, -10.0, -40.0).normalize();
    let side = fwd.cross(glam::DVec3::Y).normalize();
    let up = side.cross(fwd);
    let eye = glam::DVec3::new(0.0, 10.0, 20.0);
    vec![
        side.x,
        up.x,
        -fwd.x,
        0.0,
        side.y,
        up.y,
        -fwd.y,
        0.0,
        side.z,
        up.z,
        -fwd.z,
        0.0,
        -side.dot(eye),
        -up.dot(eye),
        fwd.dot(eye),
        1.0,
    ]
}

fn input() -> Value {
    json!({
        "world_to_eye": view(), "near": 0.5, "far": 200.0, "half_fov": 0.5,
        "light_dir_world": [0.3, -1.0, -0.2],
        "receivers": [{"min": [-50, -1, -100], "max": [50, 0, 50]}],
        "casters": [{"min": [-50, -1, -100], "max": [50, 0, 50]}],
        "map_resolution": 1024, "image_height": 1080
    })
}

fn error(req: Value) -> Value {
    let e = call(&req.to_string()).expect_err("the request must fail");
    serde_json::from_str::<Value>(&e).unwrap()["error"].clone()
}

#[test]
fn errors_carry_the_library_message_and_the_argument() {
    let mut i = input();
    i["map_resolution"] = json!(2);
    let e = error(json!({"fn": "frame", "input": i}));
    assert_eq!(e["kind"], "InvalidArgument");
    assert_eq!(e["name"], "map_resolution");
    assert_eq!(
        e["message"],
        "map_resolution must be at least 3 texels (got 2)"
    );
    let e = error(json!({"fn": "nope"}));
    assert_eq!(e["kind"], "Request");
    assert!(e["message"]
        .as_str()
        .unwrap()
        .contains("unknown function \"nope\""));
    let e = error(json!({"fn": "frame", "input": {"near": 1}}));
    assert_eq!(e["name"], "world_to_eye");
}

#[test]
fn non_finite_numbers_reach_the_library_by_name() {
    let mut i = input();
    i["far"] = json!("Infinity");
    let e = error(json!({"fn": "frame", "input": i}));
    assert_eq!(e["name"], "far");
    assert!(e["message"].as_str().unwrap().contains("inf"), "{e}");
    // A uniform map's n′ is infinite: written as the string JavaScript turns back into Infinity.
    let out = call(
        &json!({"fn": "closed", "name": "eta_from_n_prime",
                "args": {"near": 1.0, "far": 100.0, "n_prime": "Infinity"}})
        .to_string(),
    )
    .unwrap();
    // Lloyd 2006 Eq 11: η = −1 is n′ = ∞.
    assert_eq!(out, r#"{"ok":-1.0}"#);
}

#[test]
fn every_candidate_scheme_is_written_and_read_back_unchanged() {
    let camera = Camera::new(
        glam::DMat4::from_cols_slice(&view()),
        0.5,
        200.0,
        0.5,
        16.0 / 9.0,
    )
    .unwrap();
    let ground = [Aabb::new([-50.0, -1.0, -100.0], [50.0, 0.0, 50.0]).unwrap()];
    let light = glam::DVec3::new(0.3, -1.0, -0.2);
    let input = FrameInput::new(camera, light, 1024, 1080)
        .receivers(Bound::Boxes(&ground))
        .casters(Bound::Boxes(&ground));
    let all = candidates(&input);
    assert!(all.len() > 10, "{} candidates", all.len());
    let light_eye = camera.world_to_eye().transform_vector3(light);
    for s in &all {
        let j = scheme::scheme_json(s);
        let back = scheme::scheme(&j, camera.view(), light_eye).unwrap();
        assert_eq!(back.get(), *s, "{j}");
    }
}
