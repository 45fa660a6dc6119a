//! Host-vs-firmware parity: the zetafill core on a Cortex-M3 without FPU (qemu-system-arm,
//! machine lm3s6965evb) places the same shapes, bit for bit, and draws the same pixels as on
//! this host.
//!
//! The firmware (`firmware-sim/`, its own workspace) is built for `thumbv7m-none-eabi` and each
//! image run once under QEMU with semihosting and `-icount shift=0`. The scenes of
//! `zetafill_display::SCENES` run in two images, one per scalar ([`plane::PLANE_IMAGES`]:
//! `zetafill-firmware-f64` and `zetafill-firmware-fixed`, since the 2D engine compiled for both
//! scalars leaves no room in the flash budget); each prints `digest NAME COUNT HEX16`, cost,
//! memory and frame lines on stderr, writes each frame as `frame-NAME.pbm`, and logs through
//! defmt on stdout. Here the host runs every scene through the same core and the same drawing
//! code and compares, image by image: digests, pixels, memory (static + painted stack of the
//! 1,024-shape engine, and flash), the defmt log decoded by `defmt-print`, and the cost
//! figures. Every scene must run on exactly one image.
//!
//! The 3D scenes (`zetafill_display::SPACE_SCENES`) are a third image,
//! `zetafill-firmware-space`, since the 2D and 3D engines together overflow the chip's flash;
//! it prints the same digest, cost, stack and memory lines (no frames), checked the same way.
//!
//! Memory: each image's flash must stay within [`FLASH_BUDGET`] (224 KiB: the link already fails
//! beyond it, see firmware-sim/memory.x) with [`FLASH_HEADROOM`] (16 KiB) to spare, and its static RAM plus the painted stack of the
//! 1,024-shape engine (the 256-solid 3D engine in the 3D image) within [`RAM_LIMIT`] (48 KiB);
//! [`over_budget`] decides, and the figures are printed.
//!
//! The 2D images are checked in [`plane`], the 3D image in [`space`], the budgets and what
//! every image shares here.
//!
//! The Rust target, `qemu-system-arm` and `defmt-print` are installed by
//! `bash scripts/test-all.sh`. Without them these tests fail; they never skip.

mod plane;
mod space;

use std::collections::BTreeMap;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// Static RAM plus stack the engine is meant to fit (the firmware's `RAM_TARGET`).
const RAM_TARGET: u64 = 48 * 1024;
/// Static RAM plus stack beyond this fails (the firmware's `RAM_LIMIT`).
const RAM_LIMIT: u64 = RAM_TARGET;
/// Flash an image may use: the chip's 256 KiB less 32 KiB for an application's own code.
const FLASH_BUDGET: u64 = 224 * 1024;
/// Flash each image keeps free under its budget, so that the next change of the core that
/// reaches the board has room to land.
const FLASH_HEADROOM: u64 = 16 * 1024;
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

/// Builds every firmware image once (one `cargo build` makes every binary).
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

/// An image's `memory` line (bytes).
struct MemoryLine {
    stat: u64,
    stack: u64,
    total: u64,
    flash: u64,
}

/// The one `memory` line of a run.
fn memory_line(fw: &Firmware) -> MemoryLine {
    let m = lines(&fw.report, "memory");
    assert_eq!(m.len(), 1, "one memory line expected:\n{}", fw.report);
    let line = MemoryLine {
        stat: field(&m[0], "static"),
        stack: field(&m[0], "stack"),
        total: field(&m[0], "total"),
        flash: field(&m[0], "flash"),
    };
    assert_eq!(line.total, line.stat + line.stack);
    line
}

/// What an image exceeds: static RAM plus stack (`ram`) beyond [`RAM_LIMIT`], flash (`flash`,
/// the larger of the firmware's figure and the ELF's loadable bytes) beyond [`FLASH_BUDGET`].
/// Empty when it fits.
fn over_budget(image: &str, ram: u64, flash: u64) -> Vec<String> {
    let mut over = Vec::new();
    if ram > RAM_LIMIT {
        over.push(format!("{image}: static + stack = {ram} B > {RAM_LIMIT} B of RAM"));
    }
    if flash > FLASH_BUDGET {
        over.push(format!(
            "{image}: flash {flash} B > the {FLASH_BUDGET} B budget by {} B",
            flash - FLASH_BUDGET
        ));
    } else if flash + FLASH_HEADROOM > FLASH_BUDGET {
        over.push(format!(
            "{image}: flash {flash} B leaves {} B of the {FLASH_BUDGET} B budget, under the {FLASH_HEADROOM} B of headroom kept",
            FLASH_BUDGET - flash
        ));
    }
    over
}

/// Checks an image's memory line against the budgets and against its ELF, and that every
/// scene's stack held the storage it needs (`need`, by scene name); prints the figures.
fn check_memory(bin: &str, fw: &Firmware, need: impl Fn(&str) -> u64) {
    let m = memory_line(fw);
    let elf = std::fs::read(&fw.elf).expect("ELF");
    let from_elf = elf_flash_bytes(&elf);
    println!(
        "{bin} memory: static {} B + stack high-water mark {} B = {} B ({:+} B against the {RAM_TARGET} B target); \
         flash {} B, {} B left of the {FLASH_BUDGET} B budget",
        m.stat,
        m.stack,
        m.total,
        m.total as i64 - RAM_TARGET as i64,
        m.flash,
        FLASH_BUDGET as i64 - m.flash as i64
    );
    // The budget the link checked (`_flash_budget` in firmware-sim/memory.x) is this test's.
    let budget = field(&lines(&fw.report, "memory")[0], "budget");
    assert_eq!(budget, FLASH_BUDGET, "{bin}: linked against a flash budget of {budget} B");
    let over = over_budget(bin, m.total, m.flash.max(from_elf));
    assert!(over.is_empty(), "{}", over.join("\n"));
    // The firmware's flash figure (from linker symbols) agrees with the ELF's loadable bytes.
    assert!(
        from_elf.abs_diff(m.flash) <= 64,
        "{bin}: ELF loads {from_elf} B of flash, firmware says {} B",
        m.flash
    );
    // Every scene was measured on a freshly painted stack, and the deepest is the one reported.
    let per_scene = lines(&fw.report, "stack");
    assert_eq!(per_scene.len(), parse_digests(&fw.report).len(), "{bin}: one stack line a scene");
    assert_eq!(per_scene.iter().map(|f| field(f, "stack")).max(), Some(m.stack));
    // The engine's storage lives on the stack: the painted high-water mark must hold it.
    for f in &per_scene {
        let need = need(f[1]);
        assert!(
            field(f, "stack") >= need,
            "{bin} {}: stack below the {need} B of storage: painting is broken",
            f[1]
        );
    }
}

/// The budget check reports an image one byte over either budget, or one byte into the flash
/// headroom, and only then.
#[test]
fn the_budget_check_can_fail() {
    assert!(over_budget("image", RAM_LIMIT, FLASH_BUDGET - FLASH_HEADROOM).is_empty());
    assert_eq!(
        over_budget("image", RAM_LIMIT, FLASH_BUDGET - FLASH_HEADROOM + 1),
        ["image: flash 212993 B leaves 16383 B of the 229376 B budget, under the 16384 B of headroom kept"]
    );
    assert_eq!(
        over_budget("image", RAM_LIMIT, FLASH_BUDGET + 1),
        ["image: flash 229377 B > the 229376 B budget by 1 B"]
    );
    assert_eq!(
        over_budget("image", RAM_LIMIT + 1, 0),
        ["image: static + stack = 49153 B > 49152 B of RAM"]
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
    for fw in plane::plane_images().map(|(_, _, fw)| fw).chain([space::space_firmware()]) {
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
