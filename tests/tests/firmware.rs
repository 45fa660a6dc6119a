//! Host-vs-firmware parity: the zetafill core on a Cortex-M3 without FPU (qemu-system-arm,
//! machine lm3s6965evb) places the same shapes, bit for bit, and draws the same pixels as on
//! this host.
//!
//! The firmware (`firmware-sim/`, its own workspace) is built for `thumbv7m-none-eabi` and run
//! once under QEMU with semihosting and `-icount shift=0`; it runs every scene of
//! `zetafill_display::SCENES` and prints `digest NAME COUNT HEX16`, cost, memory and frame
//! lines on stderr, writes each frame as `frame-NAME.pbm`, and logs through defmt on stdout.
//! Here the host runs the same scenes through the same core and the same drawing code and
//! compares: digests, pixels, memory (static + painted stack of the 1,024-shape engine, and
//! flash), the defmt log decoded by `defmt-print`, and the cost figures.
//!
//! The 3D scenes (`zetafill_display::SPACE_SCENES`) are a second image,
//! `zetafill-firmware-space`, since the 2D and 3D engines together overflow the chip's flash;
//! it prints the same digest, cost, stack and memory lines (no frames), checked the same way.
//!
//! Memory: flash must stay within 224 KiB, and static RAM plus the painted stack of the
//! 1,024-shape engine (the 256-solid 3D engine in the 3D image) within 48 KiB
//! ([`RAM_LIMIT`]); the figures are printed.
//!
//! The Rust target, `qemu-system-arm` and `defmt-print` are installed by
//! `bash scripts/test-all.sh`. Without them these tests fail; they never skip.

use std::collections::BTreeMap;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use zetafill::{CellWords, Fixed, Placed, PlacedSolid, Scalar, SpaceStorage, Storage};
use zetafill_display::draw::{Frame, FRAME_BYTES, HEIGHT, PBM_HEADER, WIDTH};
use zetafill_display::scenes::{
    run, run_fast, Outcome, ScalarKind, Scene, SceneRegion, CAPACITY, FAST_CAPACITY, FAST_CELLS, FAST_INDEX_WORDS, INDEX_WORDS, SCENES,
};
use zetafill_display::space::{run_space, SpaceScene, SPACE_CAPACITY, SPACE_INDEX_WORDS, SPACE_SCENES};
use zetafill_tests::{run_scene, CANONICAL};

const RAM_TARGET: u64 = 48 * 1024;
const RAM_LIMIT: u64 = RAM_TARGET;
const FLASH_BUDGET: u64 = 224 * 1024;
/// A hang guard only (the run takes well under a minute); never a performance assertion.
const QEMU_LIMIT: Duration = Duration::from_secs(20 * 60);

struct Firmware {
    elf: PathBuf,
    out: PathBuf,
    /// The firmware's stderr: report lines.
    report: String,
    /// The firmware's stdout: defmt frames.
    defmt: Vec<u8>,
    exit: Option<i32>,
}

fn firmware_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("firmware-sim")
}

fn require_tool(program: &str, install: &str) {
    let found = Command::new(program)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    assert!(
        found,
        "`{program}` is not installed: the firmware tests need it ({install}, or run `bash scripts/test-all.sh`)"
    );
}

/// Builds both firmware images once (one `cargo build` makes both binaries).
fn build() -> PathBuf {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    BUILT
        .get_or_init(|| {
            require_tool("qemu-system-arm", "apt-get install qemu-system-arm");
            let dir = firmware_dir();
            let target = dir.join("target");
            let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
            let status = Command::new(cargo)
                .args(["build", "--release", "--bins"])
                .current_dir(&dir)
                .env("CARGO_TARGET_DIR", &target)
                .env_remove("RUSTFLAGS")
                .env_remove("CARGO_ENCODED_RUSTFLAGS")
                .env_remove("CARGO_BUILD_TARGET")
                .status()
                .expect("cargo runs");
            assert!(
                status.success(),
                "the firmware does not build (rustup target add thumbv7m-none-eabi?)"
            );
            target
        })
        .clone()
}

/// Runs the firmware image `bin` once under QEMU, in `target/RUN_DIR`.
fn run_image(bin: &str, run_dir: &str) -> Firmware {
    let target = build();
    let elf = target.join("thumbv7m-none-eabi/release").join(bin);
    let out = target.join(run_dir);
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).expect("output directory");
    let stdout = File::create(out.join("defmt.bin")).expect("defmt.bin");
    let stderr = File::create(out.join("report.txt")).expect("report.txt");
    let mut child = Command::new("qemu-system-arm")
        .args([
            "-cpu",
            "cortex-m3",
            "-machine",
            "lm3s6965evb",
            "-display",
            "none",
            "-serial",
            "none",
            "-monitor",
            "none",
        ])
        .args(["-semihosting-config", "enable=on,target=native", "-icount", "shift=0", "-kernel"])
        .arg(&elf)
        .current_dir(&out)
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(stderr)
        .spawn()
        .expect("qemu-system-arm starts");
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait for qemu") {
            break s;
        }
        if start.elapsed() > QEMU_LIMIT {
            let _ = child.kill();
            panic!("the firmware {bin} did not finish under QEMU (hung?)");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let report = std::fs::read_to_string(out.join("report.txt")).expect("report");
    let defmt = std::fs::read(out.join("defmt.bin")).expect("defmt log");
    Firmware {
        elf,
        out,
        report,
        defmt,
        exit: status.code(),
    }
}

/// The 2D image, run once (shared by every test in this file).
fn firmware() -> &'static Firmware {
    static FW: OnceLock<Firmware> = OnceLock::new();
    FW.get_or_init(|| run_image("zetafill-firmware-sim", "test-run"))
}

/// The 3D image, run once.
fn space_firmware() -> &'static Firmware {
    static FW: OnceLock<Firmware> = OnceLock::new();
    FW.get_or_init(|| run_image("zetafill-firmware-space", "test-run-space"))
}

/// The fields of every report line starting with `word`.
fn lines<'a>(report: &'a str, word: &str) -> Vec<Vec<&'a str>> {
    report
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|f| f.first() == Some(&word))
        .collect()
}

/// The value of `key=VALUE` among the fields.
fn field(fields: &[&str], key: &str) -> u64 {
    let prefix = format!("{key}=");
    let v = fields
        .iter()
        .find_map(|f| f.strip_prefix(prefix.as_str()))
        .unwrap_or_else(|| panic!("no {key} in {fields:?}"));
    v.parse().unwrap_or_else(|_| panic!("{key}={v} is not a number"))
}

/// `digest NAME COUNT HEX16` lines as NAME -> (count, digest).
fn parse_digests(report: &str) -> BTreeMap<String, (u64, u64)> {
    let mut m = BTreeMap::new();
    for f in lines(report, "digest") {
        assert_eq!(f.len(), 4, "malformed digest line {f:?}");
        assert_eq!(f[3].len(), 16, "digest is not 16 hex digits: {f:?}");
        let count = f[2].parse().expect("count");
        let hash = u64::from_str_radix(f[3], 16).expect("hex digest");
        assert!(m.insert(f[1].to_string(), (count, hash)).is_none(), "{} printed twice", f[1]);
    }
    m
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
    let fw = firmware();
    assert_eq!(fw.exit, Some(0), "firmware failed:\n{}", fw.report);
    assert!(fw.report.lines().any(|l| l == "done"), "no `done`:\n{}", fw.report);
    assert!(!fw.report.lines().any(|l| l.starts_with("error")), "{}", fw.report);
    assert_eq!(parse_digests(&fw.report).len(), SCENES.len());
}

#[test]
fn firmware_digests_equal_the_hosts() {
    let fw = parse_digests(&firmware().report);
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
    let fw = parse_digests(&firmware().report);
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
    let fw = firmware();
    let mut bad = Vec::new();
    for (name, host) in host_runs() {
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

/// The flash segments of the ELF (the PT_LOAD segments with a flash address): their contents.
fn elf_flash_segments(elf: &[u8]) -> Vec<&[u8]> {
    let u16_at = |o: usize| usize::from(u16::from_le_bytes([elf[o], elf[o + 1]]));
    let u32_at = |o: usize| u32::from_le_bytes([elf[o], elf[o + 1], elf[o + 2], elf[o + 3]]) as usize;
    assert_eq!(&elf[..6], b"\x7fELF\x01\x01", "not a little-endian ELF32");
    let (phoff, phentsize, phnum) = (u32_at(0x1c), u16_at(0x2a), u16_at(0x2c));
    (0..phnum)
        .map(|i| phoff + i * phentsize)
        .filter(|&ph| u32_at(ph) == 1 && u32_at(ph + 12) < 0x2000_0000)
        .map(|ph| &elf[u32_at(ph + 4)..u32_at(ph + 4) + u32_at(ph + 16)])
        .collect()
}

/// Flash bytes the ELF loads.
fn elf_flash_bytes(elf: &[u8]) -> u64 {
    elf_flash_segments(elf).iter().map(|s| s.len() as u64).sum()
}

/// Whether any flash segment holds `needle` (a path of the checkout, say).
fn flash_holds(elf: &[u8], needle: &[u8]) -> bool {
    elf_flash_segments(elf).iter().any(|s| s.windows(needle.len()).any(|w| w == needle))
}

#[test]
fn a_1024_shape_engine_fits_the_board() {
    let fw = firmware();
    let m = lines(&fw.report, "memory");
    assert_eq!(m.len(), 1, "one memory line expected:\n{}", fw.report);
    let (stat, stack, total, flash) = (
        field(&m[0], "static"),
        field(&m[0], "stack"),
        field(&m[0], "total"),
        field(&m[0], "flash"),
    );
    println!(
        "memory: static {stat} B + stack high-water mark {stack} B = {total} B ({:+} B against the {RAM_TARGET} B target); flash {flash} B (budget {FLASH_BUDGET})",
        total as i64 - RAM_TARGET as i64
    );
    assert_eq!(total, stat + stack);
    assert!(total <= RAM_LIMIT, "static + stack = {total} B > {RAM_LIMIT} B");
    assert!(flash <= FLASH_BUDGET, "flash {flash} B > 224 KiB");
    // Every scene was measured on a freshly painted stack, and the deepest is the one reported.
    let per_scene = lines(&fw.report, "stack");
    assert_eq!(per_scene.len(), SCENES.len());
    assert_eq!(per_scene.iter().map(|f| field(f, "stack")).max(), Some(stack));
    // The engine's storage lives on the stack: the painted high-water mark must hold it.
    let storage = (CAPACITY * std::mem::size_of::<Placed<f64>>() + INDEX_WORDS * 4 + FRAME_BYTES) as u64;
    // A cell-sampler scene has fewer shape slots and the cells.
    let fast_storage = (FAST_CAPACITY * std::mem::size_of::<Placed<f64>>()
        + FAST_INDEX_WORDS * 4
        + FAST_CELLS * std::mem::size_of::<CellWords>()
        + FRAME_BYTES) as u64;
    for f in &per_scene {
        let fast = SCENES.iter().any(|s| s.name == f[1] && s.fast);
        let need = if fast { fast_storage } else { storage };
        assert!(
            field(f, "stack") >= need,
            "{}: stack below the {need} B of storage: painting is broken",
            f[1]
        );
    }
    // The firmware's flash figure (from linker symbols) agrees with the ELF's loadable bytes.
    let elf = std::fs::read(&fw.elf).expect("ELF");
    let from_elf = elf_flash_bytes(&elf);
    assert!(
        from_elf.abs_diff(flash) <= 64,
        "ELF loads {from_elf} B of flash, firmware says {flash} B"
    );
}

/// The image's size must not depend on where the repository is checked out: no source path of
/// the checkout (a panic location, say) may sit in flash, where a longer path costs bytes of the
/// budget.
#[test]
fn flash_holds_no_path_of_the_checkout() {
    let root = firmware_dir().canonicalize().expect("the firmware's directory");
    let root = root.parent().expect("the repository");
    let needle = root.to_str().expect("a UTF-8 path").as_bytes();
    for fw in [firmware(), space_firmware()] {
        let elf = std::fs::read(&fw.elf).expect("ELF");
        assert!(
            !flash_holds(&elf, needle),
            "{}: flash holds the checkout's path {}",
            fw.elf.display(),
            root.display()
        );
        // The check can fail: the same image with the path written into its first flash segment.
        let first = elf_flash_segments(&elf)[0].as_ptr() as usize - elf.as_ptr() as usize;
        let mut planted = elf.clone();
        planted[first + 0x400..first + 0x400 + needle.len()].copy_from_slice(needle);
        assert!(flash_holds(&planted, needle));
    }
}

#[test]
fn cost_per_placement_is_reported_for_both_scalars() {
    let fw = firmware();
    let clock = lines(&fw.report, "clock");
    assert_eq!(clock.len(), 1, "{}", fw.report);
    let (instr, ticks) = (field(&clock[0], "instructions"), field(&clock[0], "ticks"));
    assert!(ticks > 0, "SysTick did not count");
    println!(
        "clock: {instr} instructions in {ticks} ticks ({} per tick)",
        instr as f64 / ticks as f64
    );
    let costs = lines(&fw.report, "cost");
    assert_eq!(costs.len(), SCENES.len());
    // Every scene's cost (the README's table), each checked against the host's trials.
    for name in SCENES.iter().map(|s| s.name) {
        let c = costs
            .iter()
            .find(|f| f.get(1) == Some(&name))
            .unwrap_or_else(|| panic!("no cost line for {name}"));
        let host = &host_runs()[name].outcome;
        assert_eq!(
            (field(c, "placements"), field(c, "trials")),
            (host.count, host.trials),
            "{name}: trials differ from the host"
        );
        let i = field(c, "instructions");
        assert!(i > 0);
        println!(
            "cost {name}: {} instructions per placement, {} per trial ({} placements, {} trials)",
            i / host.count,
            i / host.trials,
            host.count,
            host.trials
        );
    }
}

#[test]
fn defmt_log_decodes_on_the_host() {
    let fw = firmware();
    require_tool("defmt-print", "cargo install defmt-print --version =1.2.0 --locked");
    let out = Command::new("defmt-print")
        .arg("-e")
        .arg(&fw.elf)
        .stdin(File::open(fw.out.join("defmt.bin")).expect("defmt.bin"))
        .output()
        .expect("defmt-print runs");
    let log = String::from_utf8_lossy(&out.stdout);
    assert!(!fw.defmt.is_empty(), "no defmt frames on the firmware's stdout");
    assert!(log.contains("zetafill firmware-sim"), "decoded log:\n{log}");
    for s in SCENES {
        let expected = format!("{} ({}): {} shapes", s.name, s.scalar.name(), s.count);
        assert!(log.contains(&expected), "no `{expected}` in the decoded log:\n{log}");
    }
    assert!(log.contains("memory: static"), "decoded log:\n{log}");
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
    let fw = space_firmware();
    let m = lines(&fw.report, "memory");
    assert_eq!(m.len(), 1, "one memory line expected:\n{}", fw.report);
    let (stat, stack, total, flash) = (
        field(&m[0], "static"),
        field(&m[0], "stack"),
        field(&m[0], "total"),
        field(&m[0], "flash"),
    );
    println!("3D image memory: static {stat} B + stack high-water mark {stack} B = {total} B; flash {flash} B (budget {FLASH_BUDGET})");
    assert_eq!(total, stat + stack);
    assert!(total <= RAM_LIMIT, "static + stack = {total} B > {RAM_LIMIT} B");
    assert!(flash <= FLASH_BUDGET, "flash {flash} B > 224 KiB");
    let per_scene = lines(&fw.report, "stack");
    assert_eq!(per_scene.len(), SPACE_SCENES.len());
    assert_eq!(per_scene.iter().map(|f| field(f, "stack")).max(), Some(stack));
    let storage = (SPACE_CAPACITY * std::mem::size_of::<PlacedSolid<f64>>() + SPACE_INDEX_WORDS * 4) as u64;
    for f in &per_scene {
        assert!(
            field(f, "stack") >= storage,
            "{}: stack below the {storage} B of storage: painting is broken",
            f[1]
        );
    }
    let elf = std::fs::read(&fw.elf).expect("ELF");
    assert!(elf_flash_bytes(&elf).abs_diff(flash) <= 64, "ELF and firmware disagree on flash");
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

/// The firmware's defmt log decoded by `defmt-print`.
fn decoded(fw: &Firmware) -> String {
    require_tool("defmt-print", "cargo install defmt-print --version =1.2.0 --locked");
    let out = Command::new("defmt-print")
        .arg("-e")
        .arg(&fw.elf)
        .stdin(File::open(fw.out.join("defmt.bin")).expect("defmt.bin"))
        .output()
        .expect("defmt-print runs");
    String::from_utf8_lossy(&out.stdout).into_owned()
}
