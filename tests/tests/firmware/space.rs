//! The 3D image: every scene of `zetafill_display::SPACE_SCENES` prints the host's digest, and
//! the noise fields the host's bits.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use zetafill::space::{Placed as PlacedSolid, Storage as SpaceStorage};
use zetafill::{Fixed, Scalar};
use zetafill_display::scenes::{Outcome, ScalarKind};
use zetafill_display::space::{run_space, SpaceScene, SPACE_CAPACITY, SPACE_INDEX_WORDS, SPACE_SCENES};

use crate::{check_memory, decoded, field, lines, parse_digests, run_image, Firmware};

/// The 3D image, run once.
pub(crate) fn space_firmware() -> &'static Firmware {
    static FW: OnceLock<Firmware> = OnceLock::new();
    FW.get_or_init(|| run_image("zetafill-firmware-space", "test-run-space"))
}

fn host_space_run<S: Scalar + Default>(scene: &SpaceScene) -> Outcome {
    let mut solids = vec![PlacedSolid::<S>::default(); SPACE_CAPACITY];
    let mut index = vec![0u32; SPACE_INDEX_WORDS];
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    run_space(scene, storage, || 0).unwrap_or_else(|e| panic!("{}: {e}", scene.name))
}

/// Every 3D scene run on this host, through the same core as the firmware.
fn host_space_runs() -> &'static BTreeMap<&'static str, Outcome> {
    static RUNS: OnceLock<BTreeMap<&'static str, Outcome>> = OnceLock::new();
    RUNS.get_or_init(|| {
        SPACE_SCENES
            .iter()
            .map(|s| {
                let o = match s.scalar {
                    ScalarKind::F64 => host_space_run::<f64>(s),
                    ScalarKind::Fixed => host_space_run::<Fixed>(s),
                };
                (s.name, o)
            })
            .collect()
    })
}

#[test]
fn space_firmware_runs_every_3d_scene_and_exits_zero() {
    let fw = space_firmware();
    assert_eq!(fw.exit, Some(0), "3D firmware failed:\n{}", fw.report);
    assert!(fw.report.lines().any(|l| l == "done"), "no `done`:\n{}", fw.report);
    assert!(!fw.report.lines().any(|l| l.starts_with("error")), "{}", fw.report);
    assert_eq!(parse_digests(&fw.report).len(), SPACE_SCENES.len());
    assert!(SPACE_SCENES.iter().any(|s| s.scalar == ScalarKind::Fixed) && SPACE_SCENES.iter().any(|s| s.scalar == ScalarKind::F64));
}

#[test]
fn space_firmware_digests_equal_the_hosts() {
    let fw = parse_digests(&space_firmware().report);
    let host = host_space_runs();
    let mut bad = Vec::new();
    for (name, o) in host {
        match fw.get(*name) {
            Some(&got) if got == (o.count, o.digest) => {}
            got => bad.push(format!("{name}: firmware {got:?}, host {} {:016x}", o.count, o.digest)),
        }
    }
    assert!(
        bad.is_empty(),
        "the Cortex-M3 and the host disagree on 3D scenes:\n{}",
        bad.join("\n")
    );
    for (name, (count, hash)) in &fw {
        println!("digest {name} {count} {hash:016x}");
    }
    // Fixed point and f64 place different solids from the same parameters.
    assert_ne!(fw.get("spheres-box"), fw.get("spheres-box-fixed"));
}

/// Value and gradient noise, open and periodic, give the same bits on the Cortex-M3 (software
/// floating point) as on the host.
#[test]
fn noise_fields_are_the_same_bits_on_the_board() {
    let fw = space_firmware();
    let got = lines(&fw.report, "noise");
    assert_eq!(got.len(), 1, "one noise line expected:\n{}", fw.report);
    let host = zetafill_display::noise::noise_digest().expect("noise fields");
    assert_eq!(got[0].get(1).copied(), Some(format!("{host:016x}").as_str()));
    // The comparison can fail: another seed gives another digest.
    let other = zetafill::Noise::new(zetafill::NoiseKind::Gradient, 12, 17.0, 5, 0.55, None).expect("a field");
    assert_ne!(
        other.at(1.0, 2.0),
        zetafill::Noise::new(zetafill::NoiseKind::Gradient, 11, 17.0, 5, 0.55, None)
            .expect("a field")
            .at(1.0, 2.0)
    );
}

#[test]
fn a_256_solid_engine_fits_the_board() {
    let storage = (SPACE_CAPACITY * std::mem::size_of::<PlacedSolid<f64>>() + SPACE_INDEX_WORDS * 4) as u64;
    check_memory("zetafill-firmware-space", space_firmware(), |_| storage);
}

#[test]
fn space_cost_per_placement_is_reported() {
    let fw = space_firmware();
    let costs = lines(&fw.report, "cost");
    assert_eq!(costs.len(), SPACE_SCENES.len());
    for s in SPACE_SCENES {
        let c = costs
            .iter()
            .find(|f| f.get(1) == Some(&s.name))
            .unwrap_or_else(|| panic!("no cost line for {}", s.name));
        let host = &host_space_runs()[s.name];
        assert_eq!(
            (field(c, "placements"), field(c, "trials")),
            (host.count, host.trials),
            "{}: trials differ",
            s.name
        );
        let i = field(c, "instructions");
        assert!(i > 0);
        println!(
            "cost {}: {} instructions per placement, {} per trial ({} placements, {} trials)",
            s.name,
            i / host.count,
            i / host.trials,
            host.count,
            host.trials
        );
    }
    let log = decoded(space_firmware());
    for s in SPACE_SCENES {
        let expected = format!("{} ({}): {} solids", s.name, s.scalar.name(), s.count);
        assert!(log.contains(&expected), "no `{expected}` in the decoded log:\n{log}");
    }
}
