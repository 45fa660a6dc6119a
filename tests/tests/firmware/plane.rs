//! The 2D images: every scene of `zetafill_display::SCENES` runs on the image of its scalar,
//! and prints the host's digests and draws the host's pixels.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use zetafill::{CellWords, Fixed, Placed, Scalar, Storage};
use zetafill_display::draw::{Frame, FRAME_BYTES, HEIGHT, PBM_HEADER, WIDTH};
use zetafill_display::scenes::{
    run, run_fast, Outcome, ScalarKind, Scene, SceneRegion, CAPACITY, FAST_CAPACITY, FAST_CELLS, FAST_INDEX_WORDS, INDEX_WORDS, SCENES,
};
use zetafill_tests::{run_scene, CANONICAL};

use crate::{check_memory, decoded, field, lines, parse_digests, run_image, Firmware};

/// The 2D images and the scalar whose scenes each runs.
pub(crate) const PLANE_IMAGES: [(&str, ScalarKind); 2] = [
    ("zetafill-firmware-f64", ScalarKind::F64),
    ("zetafill-firmware-fixed", ScalarKind::Fixed),
];

/// The 2D image `PLANE_IMAGES[i]`, run once (shared by every test).
fn plane_firmware(i: usize) -> &'static Firmware {
    static FW: [OnceLock<Firmware>; PLANE_IMAGES.len()] = [const { OnceLock::new() }; PLANE_IMAGES.len()];
    FW[i].get_or_init(|| run_image(PLANE_IMAGES[i].0, &format!("test-run-{}", PLANE_IMAGES[i].1.name())))
}

/// Every 2D image, run: its name, its scenes and its run.
pub(crate) fn plane_images() -> impl Iterator<Item = (&'static str, Vec<&'static Scene>, &'static Firmware)> {
    (0..PLANE_IMAGES.len()).map(|i| {
        let (bin, scalar) = PLANE_IMAGES[i];
        (bin, SCENES.iter().filter(|s| s.scalar == scalar).collect(), plane_firmware(i))
    })
}

/// The 2D image that runs `scene`.
fn plane_image_of(scene: &Scene) -> &'static Firmware {
    let i = PLANE_IMAGES
        .iter()
        .position(|&(_, scalar)| scalar == scene.scalar)
        .unwrap_or_else(|| panic!("{}: no image runs its scalar", scene.name));
    plane_firmware(i)
}

/// The digests of every 2D image, together (a scene printed by two images is an error).
fn plane_digests() -> BTreeMap<String, (u64, u64)> {
    let mut all = BTreeMap::new();
    for (bin, _, fw) in plane_images() {
        for (name, d) in parse_digests(&fw.report) {
            assert!(
                all.insert(name.clone(), d).is_none(),
                "{name} printed by two images (the second {bin})"
            );
        }
    }
    all
}

struct HostRun {
    outcome: Outcome,
    pbm: Vec<u8>,
}

fn host_run_on<S: Scalar + Default>(scene: &Scene) -> HostRun {
    let mut shapes = vec![Placed::<S>::default(); CAPACITY];
    let mut index = vec![0u32; INDEX_WORDS];
    // The board's cell storage: when it runs out the sampler stops refining, so the host must
    // lend the same number of cells to place the same shapes.
    let mut cells = vec![[0u64; 4]; FAST_CELLS];
    let mut frame = Frame::new();
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let outcome = if scene.fast {
        run_fast(scene, storage, &mut cells, &mut frame, || 0)
    } else {
        run(scene, storage, &mut frame, || 0)
    }
    .unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    let mut pbm = PBM_HEADER.to_vec();
    pbm.extend_from_slice(frame.data());
    HostRun { outcome, pbm }
}

/// Every scene run on this host, through the same core and drawing code as the firmware.
fn host_runs() -> &'static BTreeMap<&'static str, HostRun> {
    static RUNS: OnceLock<BTreeMap<&'static str, HostRun>> = OnceLock::new();
    RUNS.get_or_init(|| {
        SCENES
            .iter()
            .map(|s| {
                let r = match s.scalar {
                    ScalarKind::F64 => host_run_on::<f64>(s),
                    ScalarKind::Fixed => host_run_on::<Fixed>(s),
                };
                (s.name, r)
            })
            .collect()
    })
}

/// Every scene whose firmware digest differs from the host's (or is missing), described.
fn digest_mismatches(fw: &BTreeMap<String, (u64, u64)>, host: &BTreeMap<&str, HostRun>) -> Vec<String> {
    let mut bad = Vec::new();
    for (name, h) in host {
        let want = (h.outcome.count, h.outcome.digest);
        match fw.get(*name) {
            Some(&got) if got == want => {}
            Some(got) => bad.push(format!(
                "{name}: firmware {} {:016x}, host {} {:016x}",
                got.0, got.1, want.0, want.1
            )),
            None => bad.push(format!("{name}: no digest from the firmware")),
        }
    }
    bad
}

/// Compares two PBM images pixel by pixel: `Err` says how many pixels differ and the first.
fn compare_pbm(firmware: &[u8], host: &[u8]) -> Result<(), String> {
    let data = |img: &[u8]| -> Result<Vec<u8>, String> {
        let d = img.strip_prefix(PBM_HEADER).ok_or("not a binary PBM of the display's size")?;
        if d.len() != FRAME_BYTES {
            return Err(format!("{} data bytes, expected {FRAME_BYTES}", d.len()));
        }
        Ok(d.to_vec())
    };
    let (a, b) = (data(firmware)?, data(host)?);
    let stride = WIDTH.div_ceil(8);
    let mut diff = Vec::new();
    for y in 0..HEIGHT {
        for x in 0..WIDTH {
            let bit = |d: &[u8]| d[y * stride + x / 8] >> (7 - x % 8) & 1;
            if bit(&a) != bit(&b) {
                diff.push((x, y));
            }
        }
    }
    match diff.first() {
        None => Ok(()),
        Some(first) => Err(format!("{} pixels differ, the first at {first:?}", diff.len())),
    }
}

#[test]
fn firmware_runs_every_scene_and_exits_zero() {
    for (bin, scenes, fw) in plane_images() {
        assert_eq!(fw.exit, Some(0), "{bin} failed:\n{}", fw.report);
        assert!(fw.report.lines().any(|l| l == "done"), "{bin}: no `done`:\n{}", fw.report);
        assert!(!fw.report.lines().any(|l| l.starts_with("error")), "{bin}:\n{}", fw.report);
        let ran: Vec<String> = parse_digests(&fw.report).into_keys().collect();
        let mut want: Vec<String> = scenes.iter().map(|s| s.name.to_string()).collect();
        want.sort();
        assert_eq!(ran, want, "{bin} runs other scenes than its scalar's");
    }
    // Every scene runs on one image.
    assert_eq!(plane_digests().len(), SCENES.len());
}

#[test]
fn firmware_digests_equal_the_hosts() {
    let fw = plane_digests();
    let bad = digest_mismatches(&fw, host_runs());
    assert!(bad.is_empty(), "the Cortex-M3 and the host disagree:\n{}", bad.join("\n"));
    for (name, (count, hash)) in &fw {
        println!("digest {name} {count} {hash:016x}");
    }
}

#[test]
fn canonical_runs_are_the_golden_scenes() {
    // The firmware's canonical scenes are exactly tests/src/lib.rs CANONICAL (whose digests
    // tests/tests/golden.rs pins), and print exactly what that reference run gives.
    let fw = plane_digests();
    for c in &CANONICAL {
        let s = SCENES
            .iter()
            .find(|s| s.name == c.name)
            .unwrap_or_else(|| panic!("{} is not a firmware scene", c.name));
        let region = SceneRegion::Rect(c.size.0, c.size.1, c.periodic);
        let same = (s.scalar, s.shapes, s.rotate, s.region, s.c, s.n_offset, s.gap, s.seed, s.count)
            == (ScalarKind::F64, &[c.shape][..], c.rotate, region, c.c, c.n, 0.0, c.seed, c.count);
        assert!(same, "{}: firmware scene {s:?} differs from the canonical {c:?}", c.name);
        let (n, h, _) = run_scene(c, 1 << 14);
        assert_eq!(
            fw.get(c.name),
            Some(&(n, h)),
            "{}: firmware digest differs from the golden run",
            c.name
        );
    }
    let circles = SCENES.iter().find(|s| s.name == "circles").expect("circles");
    let fixed = SCENES.iter().find(|s| s.name == "circles-fixed").expect("circles-fixed");
    assert_eq!(
        *fixed,
        Scene {
            name: "circles-fixed",
            scalar: ScalarKind::Fixed,
            ..*circles
        }
    );
    assert_ne!(fw.get("circles"), fw.get("circles-fixed"), "the scalars are expected to differ");
}

#[test]
fn firmware_frames_equal_the_hosts_pixel_for_pixel() {
    let mut bad = Vec::new();
    for (name, host) in host_runs() {
        let fw = plane_image_of(SCENES.iter().find(|s| s.name == *name).expect("a scene"));
        let listed = lines(&fw.report, "frame").iter().any(|f| f.get(1) == Some(name));
        let path = fw.out.join(format!("frame-{name}.pbm"));
        let Ok(img) = std::fs::read(&path) else {
            bad.push(format!("{name}: no frame {} (listed: {listed})", path.display()));
            continue;
        };
        if let Err(e) = compare_pbm(&img, &host.pbm) {
            let _ = std::fs::write(fw.out.join(format!("host-{name}.pbm")), &host.pbm);
            bad.push(format!("{name}: {e} (host image written beside it)"));
        }
        assert!(host.pbm[PBM_HEADER.len()..].iter().any(|&b| b != 0), "{name}: empty picture");
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_comparisons_can_fail() {
    let host = host_runs();
    // A digest one bit off is reported.
    let mut fw: BTreeMap<String, (u64, u64)> = host
        .iter()
        .map(|(n, r)| (n.to_string(), (r.outcome.count, r.outcome.digest)))
        .collect();
    assert!(digest_mismatches(&fw, host).is_empty());
    fw.get_mut("circles-fixed").expect("scene").1 ^= 1;
    fw.remove("rects");
    let bad = digest_mismatches(&fw, host);
    assert_eq!(bad.len(), 2, "{bad:?}");
    assert!(bad.iter().any(|b| b.starts_with("circles-fixed:")) && bad.iter().any(|b| b.starts_with("rects:")));
    // One pixel off is reported, with its place.
    let img = &host["circles"].pbm;
    assert_eq!(compare_pbm(img, img), Ok(()));
    let mut off = img.clone();
    off[PBM_HEADER.len() + 16 * 40 + 3] ^= 0b0001_0000;
    assert_eq!(compare_pbm(&off, img), Err("1 pixels differ, the first at (27, 40)".into()));
    assert!(compare_pbm(&img[..100], img).is_err());
    // The drawing itself tells scenes apart.
    assert!(compare_pbm(&host["circles"].pbm, &host["squares"].pbm).is_err());
}

#[test]
fn a_1024_shape_engine_fits_the_board() {
    let storage = (CAPACITY * std::mem::size_of::<Placed<f64>>() + INDEX_WORDS * 4 + FRAME_BYTES) as u64;
    // A cell-sampler scene has fewer shape slots and the cells.
    let fast_storage = (FAST_CAPACITY * std::mem::size_of::<Placed<f64>>()
        + FAST_INDEX_WORDS * 4
        + FAST_CELLS * std::mem::size_of::<CellWords>()
        + FRAME_BYTES) as u64;
    for (bin, scenes, fw) in plane_images() {
        check_memory(bin, fw, |name| {
            let scene = scenes.iter().find(|s| s.name == name);
            let scene = scene.unwrap_or_else(|| panic!("{bin}: a stack line for {name}, not one of its scenes"));
            if scene.fast {
                fast_storage
            } else {
                storage
            }
        });
    }
}

#[test]
fn cost_per_placement_is_reported_for_both_scalars() {
    for (bin, scenes, fw) in plane_images() {
        let clock = lines(&fw.report, "clock");
        assert_eq!(clock.len(), 1, "{bin}:\n{}", fw.report);
        let (instr, ticks) = (field(&clock[0], "instructions"), field(&clock[0], "ticks"));
        assert!(ticks > 0, "{bin}: SysTick did not count");
        println!(
            "{bin} clock: {instr} instructions in {ticks} ticks ({} per tick)",
            instr as f64 / ticks as f64
        );
        let costs = lines(&fw.report, "cost");
        assert_eq!(costs.len(), scenes.len(), "{bin}: one cost line a scene");
        // Every scene's cost (the table of docs/firmware.md), each checked against the host's trials.
        for name in scenes.iter().map(|s| s.name) {
            let c = costs
                .iter()
                .find(|f| f.get(1) == Some(&name))
                .unwrap_or_else(|| panic!("{bin}: no cost line for {name}"));
            let host = &host_runs()[name].outcome;
            assert_eq!(
                (field(c, "placements"), field(c, "trials")),
                (host.placed, host.trials),
                "{name}: trials differ from the host"
            );
            let i = field(c, "instructions");
            assert!(i > 0);
            println!(
                "cost {name}: {} instructions per placement, {} per trial ({} placements, {} trials)",
                i / host.placed,
                i / host.trials,
                host.placed,
                host.trials
            );
        }
    }
}

#[test]
fn defmt_log_decodes_on_the_host() {
    for (bin, scenes, fw) in plane_images() {
        assert!(!fw.defmt.is_empty(), "{bin}: no defmt frames on the firmware's stdout");
        let log = decoded(fw);
        let start = format!("{bin}: {} scenes, engine capacity {CAPACITY} shapes", scenes.len());
        assert!(log.contains(&start), "{bin}: no `{start}` in the decoded log:\n{log}");
        for s in scenes {
            let expected = format!("{} ({}): {} shapes", s.name, s.scalar.name(), s.count);
            assert!(log.contains(&expected), "{bin}: no `{expected}` in the decoded log:\n{log}");
        }
        assert!(log.contains("memory: static"), "{bin}: decoded log:\n{log}");
    }
}
