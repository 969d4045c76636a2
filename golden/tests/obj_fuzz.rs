//! A fuzzing harness for the OBJ and MTL loader, as proptests (issue 18): OBJ files built from valid
//! and broken statements, and valid files mutated byte by byte, with MTL libraries of the same kinds.
//! Whatever the input, loading returns a mesh or an error naming the file, never panics, and an
//! accepted mesh is well formed (indices in range, finite unit normals, materials in range) and renders
//! through the golden model without a panic. Bounded: `PROPTEST_CASES` (default 256 per property).

use golden::format::Screen;
use golden::render::{render, RenderOptions};
use golden::scene::obj::load_obj;
use golden::shade::Shading;
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

fn scratch(tag: &str) -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let d = std::env::temp_dir().join(format!("golden-objfuzz-{}-{tag}-{}", std::process::id(), N.fetch_add(1, Ordering::Relaxed)));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A number as an OBJ file might spell it: ordinary, extreme, or not a number at all.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        1 => prop::sample::select(vec!["0", "-0", "1e15", "-1e15", "1e16", "1e39", "1e309", "nan", "inf", "-inf", "1e-300", "0x10", "", "1.2.3", "+3", "٣"])
            .prop_map(String::from),
    ]
}

/// A face vertex reference: ordinary, negative, zero, huge, or malformed.
fn reference() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (1i64..12).prop_map(|i| i.to_string()),
        1 => (-6i64..0).prop_map(|i| i.to_string()),
        1 => (1i64..12, 1i64..6).prop_map(|(v, n)| format!("{v}//{n}")),
        1 => (1i64..12, 1i64..6, 1i64..6).prop_map(|(v, t, n)| format!("{v}/{t}/{n}")),
        1 => prop::sample::select(vec!["0", "99999999999999999999", "1/", "//", "a", "1/2/3/4", "-0"]).prop_map(String::from),
    ]
}

/// One OBJ statement, valid or not.
fn statement() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => (number(), number(), number()).prop_map(|(x, y, z)| format!("v {x} {y} {z}")),
        1 => (number(), number(), number(), number()).prop_map(|(x, y, z, w)| format!("v {x} {y} {z} {w}")),
        2 => (number(), number(), number()).prop_map(|(x, y, z)| format!("vn {x} {y} {z}")),
        1 => (number(), number()).prop_map(|(u, v)| format!("vt {u} {v}")),
        6 => prop::collection::vec(reference(), 0..7).prop_map(|r| format!("f {}", r.join(" "))),
        1 => prop::sample::select(vec!["usemtl red", "usemtl", "usemtl nosuch", "mtllib m.mtl", "mtllib gone.mtl", "mtllib", "o thing", "g", "s off", "l 1 2", "p 1", "# comment", "", "   ", "\u{feff}v 1 2 3", "v 1 2 3 # note"])
            .prop_map(String::from),
        1 => "[ -~]{0,20}",
    ]
}

/// An MTL library: valid statements, broken numbers, or nothing useful.
fn mtl() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            prop::sample::select(vec!["newmtl red", "newmtl", "Kd 0.8 0.1 0.1", "Ka 0 0 0", "Ks 1 1 1", "Ns 96", "Ns -5", "Ns nan", "Kd 1", "Kd a b c", "d 0.5", "illum 2", "map_Kd x.png"])
                .prop_map(String::from),
            (number(), number(), number()).prop_map(|(a, b, c)| format!("Kd {a} {b} {c}")),
            number().prop_map(|n| format!("Ns {n}")),
        ],
        0..10,
    )
    .prop_map(|l| l.join("\n"))
}

/// A valid triangle mesh, as text, to mutate.
fn valid_obj() -> impl Strategy<Value = String> {
    (prop::collection::vec((-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0), 3..9), 1usize..6).prop_map(|(vs, faces)| {
        let mut t = String::from("mtllib m.mtl\nusemtl red\n");
        for (x, y, z) in &vs {
            t.push_str(&format!("v {x} {y} {z}\n"));
        }
        for k in 0..faces {
            let n = vs.len();
            t.push_str(&format!("f {} {} {}\n", k % n + 1, (k + 1) % n + 1, (k + 2) % n + 1));
        }
        t
    })
}

/// Load `obj` (with `m.mtl` beside it) and check what came back.
fn check(obj: &[u8], mtl_text: &str) -> Result<(), TestCaseError> {
    let dir = scratch("case");
    std::fs::write(dir.join("m.mtl"), mtl_text).unwrap();
    let path = dir.join("fuzz.obj");
    std::fs::write(&path, obj).unwrap();
    let result = std::panic::catch_unwind(|| load_obj(&path));
    let loaded = result.map_err(|_| TestCaseError::fail("load_obj panicked"))?;
    match loaded {
        Err(e) => prop_assert!(e.contains("fuzz.obj"), "the error does not name the file: {e}"),
        Ok(mesh) => {
            prop_assert!(!mesh.triangles.is_empty());
            for t in &mesh.triangles {
                prop_assert!(t.v.iter().all(|&i| (i as usize) < mesh.positions.len()));
                prop_assert!(t.n.iter().all(|&i| (i as usize) < mesh.normals.len()));
                prop_assert!((t.material as usize) < mesh.materials.len());
            }
            prop_assert!(mesh.positions.iter().flatten().all(|c| c.is_finite()));
            for n in &mesh.normals {
                let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                prop_assert!((l - 1.0).abs() < 1e-9, "normal {n:?} is not unit length");
            }
            // It renders (or is refused with a reason) without a panic.
            let screen = Screen::new(16, 12).unwrap();
            let r = std::panic::catch_unwind(|| {
                let opts = RenderOptions::for_scene(&mesh, screen, Shading::Gouraud);
                render(&mesh, &opts).map(|_| ())
            });
            prop_assert!(r.is_ok(), "rendering an accepted mesh panicked");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn generated_obj_files_load_or_fail_with_the_file_named_and_never_panic(lines in prop::collection::vec(statement(), 0..24), m in mtl()) {
        check(lines.join("\n").as_bytes(), &m)?;
    }

    #[test]
    fn mutated_valid_obj_files_load_or_fail_with_the_file_named_and_never_panic(
        text in valid_obj(),
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
        m in mtl(),
    ) {
        let mut bytes = text.into_bytes();
        for (at, byte, kind) in edits {
            if bytes.is_empty() {
                break;
            }
            let i = at.index(bytes.len());
            match kind {
                0 => bytes[i] = byte,
                1 => bytes.truncate(i),
                _ => bytes.insert(i, byte),
            }
        }
        check(&bytes, &m)?;
    }
}
