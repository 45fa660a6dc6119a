//! The output corpus: the SHA-256 of what each of a fixed list of commands writes, pinned.
//!
//! The list covers every subcommand, every output format, every built-in machine profile and
//! a profile file, every shape and region kind, both samplers and both scalars, the colour,
//! layer, page, hatch and relief flags, and one halted run. The commands run in order in one
//! folder, so later ones read what earlier ones wrote (a fill's JSON for `--sites-from` and
//! `stats dimension`, a profile written by `machines show`). What is hashed is the `-o` file,
//! or standard output for commands that print.
//!
//! Any changed byte fails the test. That is the point: the internals may be rebuilt freely, the
//! files may not change. To re-mint after a change that is meant to alter outputs (say which
//! and why in the commit), run
//! `cargo test -p zetafill-cli --release --test corpus -- --nocapture` and copy the printed
//! table into `CORPUS`.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{tmp, zf};
use sha2::{Digest, Sha256};
use std::path::Path;

/// A palette used by several entries.
const P5: &str = "264653,2a9d8f,e9c46a,f4a261,e76f51";

/// (command, expected exit code, SHA-256 of its output). `{P5}` stands for the palette above.
const CORPUS: &[(&str, i32, &str)] = &[
    // fill: shapes, regions, stop conditions, formats
    ("fill --count 300 -o circles.svg", 0, "8e3cf64a23cbe4fc1a0e6bf574402689f3408dd445365dc048ff9c1edf3acedb"),
    ("fill --c 1.25 --count 400 -o fill.json", 0, "ddb7c5a6b93c81f1d5d414ba35e90cb2259c1038d63148550e797840fdc17d0c"),
    ("fill --shape square --count 300 --seed 2 -o squares.json", 0, "b07261c4d08957558509ac8a7b858e4a2ea5ceda9054e2f7a53a045eb783c47c"),
    ("fill --shape rect:2.5 --rotate none --region rect:200:120 --c 1.2 --n-offset 3 --count 300 --seed 3 -o rects.csv", 0, "9e35d94312552c7ed40c3e7b7ae11470629a011a8b63dd797198787961f263b4"),
    ("fill --shape triangle --count 200 --seed 4 --style filled -o triangles.svg", 0, "8e09a92b4972e94809be0bc36233c13f755089b858a94a1809614ca71f73154c"),
    ("fill --shape polygon:6 --region circle:80 --count 200 -o hexagons.json", 0, "a649fb189cd75ded65975fe0b88df716603ed51a5bd08da1fa12a82e4ec2489a"),
    ("fill --shape star:5:0.45 --c 1.2 --n-offset 3 --count 200 --seed 2 -o stars.svg", 0, "5ddff1fffe638cdfb0688d0685fadc4f3bd8ad7754c3674a721a5a62732ba2e5"),
    ("fill --shape ring:0.5 --region annulus:90:30 --c 1.25 --n-offset 5 --count 200 -o rings.json", 0, "bd7f31c5109ced8014d5128a0aa5fab4784be11c744594dca83aa1026b4da132"),
    ("fill --shape blob:0.2 --c 1.25 --n-offset 2 --count 200 -o blobs.svg", 0, "cfac9a618cdf74808fecc517ec362ee6094fd2d1d7201e806f21b56c00097fb3"),
    ("fill --shape mix:circle,square,triangle --mix-order random --count 300 --color-by kind --palette 264653,2a9d8f,e9c46a --style filled -o mix.svg", 0, "012204e999efd36f486e48da14ea00999a6e746bb6371c577e13864bb23bba50"),
    ("fill --shape mix:square,ring:0.4 --count 200 -o mix.json", 0, "547c624257a6f5ff6b4523039465d25142d066d2c6a7345b93602cebfa08c179"),
    ("fill --region polygon:0,0,90,0,90,90,0,90/30,30,60,30,60,60 --c 1.25 --n-offset 3 --count 200 --gap 0.5 -o holed.json", 0, "3960acf75484bdb7cdff3b07f24dc648dd35d471d8d2497a047cb5b363dd699b"),
    ("fill --region svg:outline.svg --c 1.25 --n-offset 3 --count 200 -o svg-region.svg", 0, "1d1bef87c4ab853b858cb51e2f49dfeb0cf5053f88707f7c84ea0584d30f297e"),
    ("fill --shape square --periodic --region rect:150:150 --c 1.25 --n-offset 2 --count 300 -o periodic.svg", 0, "a1b4e51f41e5db8ca2fb210bda863f4c0417fd416f5ee66194ef434298a55217"),
    ("fill --periodic --count 300 --machine grbl-laser -o periodic.gcode", 0, "3708cb4488642ab85fcf6d3a78596aeaef1fa3f91033715dcb7fcc453d3f747c"),
    ("fill --sampler reference --count 300 -o reference.json", 0, "7f30b4114aa80d3b13b40f10d29b33c87fc2ae7d659b08a66af54efff7ef9989"),
    ("fill --scalar fixed --shape square --count 300 --format digest -o fixed.txt", 0, "4d48920e8582e751a45ed21e32974b0142d51e58da4cfa0e7d317fa18f37ac79"),
    ("fill --dimension 1.6 --fill 0.5 -o dimension.csv", 0, "11c42a1c6af1ee252ee3ee07040c78ccae137f2138b273964873ca8e915b75ba"),
    ("fill --min-size 3 --shape polygon:5 --rotate none -o min-size.json", 0, "96527abcbb92a53a4402e7459571204df4e9d3fd2c339206faf162414b47407a"),
    ("fill --gap 1 --shape square --rotate none --c 1.25 --n-offset 2 --count 200 --boundary -o gap.svg", 0, "75987f9749bc0958bce40f226c8b51b0b2ba2306bd1041b0097d3f5346920a7c"),
    ("fill --c 1.45 --count 300 --max-trials 300 -o halted.json", 3, "e84ac5fe26d1a22d569fddd87238a9273b4f63735d3e34c608e7f1986d879c3f"),
    // fill: pictures and colour
    ("fill --count 300 --style filled --palette {P5} --background fefae0 --pixels 200 -o palette.png", 0, "45744172ebbb66fc6a95706f5ea3d1f244b92980c78b2deec708e7c58a90e2ab"),
    ("fill --count 200 --boundary --pen-width 0.5 --region circle:60 --dpi 48 -o circle.png", 0, "6a774411a8f96b7779e8c5ada65fabc13ab49c31477c07153cb0738b6cd5b560"),
    ("fill --count 300 --periodic --relief dome --pixels 160 -o relief-dome.png", 0, "da5244fa8cfa4cf7114df1d8d3581c7782ae6d0abb154290703d59aea9c9e789"),
    ("fill --shape star:5:0.45 --c 1.2 --n-offset 3 --count 200 --relief cone --pixels 160 -o relief-cone.png", 0, "0b73836a7425c91e6eeca0ae07f30ab530ed6505e2b130fcdbb944803ba7ab2e"),
    ("fill --shape ring:0.5 --n-offset 2 --count 200 --relief flat --pixels 120 -o relief-flat.png", 0, "42a2b786b630626cc97e64aa6a9a918e4d0929ff0c7cacbb71c1b81296e6fe76"),
    ("fill --count 300 --voronoi -o cobbles.svg", 0, "a71c06101b00d436c986becdbf0cfe0c6604ddbc64ee86f72a53e7128ca7759a"),
    ("fill --count 300 --c 1.2 --n-offset 2 --periodic --region rect:120:120 --voronoi --style filled --palette {P5} --color-by random --background fefae0 --pixels 200 -o glass.png", 0, "9854d42406a202784ba75f35f7d71467ae0a9ca4c4e530c126ac5fc45a88e10f"),
    // fill: plotters and lasers
    ("fill --count 300 --region rect:180:180 --page a4 --center --layers size-bands:3 -o bands.svg", 0, "a7cec6aa4c7c3bc06170d4a2cb5bb4bd6e0dc92270f7b21c8dfe6183aea76951"),
    ("fill --count 300 --page a3-landscape --fit --palette 1d3557,e63946 --color-by random --layers colours -o pens.svg", 0, "5d8c29c2d7d457651c682e119e0c938500a91c66a7030c76677caa93aa6abb5d"),
    ("fill --count 300 --palette 1d3557,e63946 --color-by cycle --layers colours --machine grbl-servo-pen -o pens.gcode", 0, "88063b00c627f1a192df52c6e691dbbf71ac582cc212e27b36489e0d90bda6d6"),
    ("fill --count 300 --machine z-lift-pen --order greedy --no-arcs -o z-lift.nc", 0, "90f43a07ac8c1d0ca6a58b40f3c4dd48318562a9b082487d39d4b8a5bbf0fd25"),
    ("fill --count 300 --machine grbl-laser --power 600 --passes 2 --order none -o cut.nc", 0, "b5df4cc1a0289c9cb83f37bf74accb533111b29e2f9356a26950ee81b23f4d2a"),
    ("fill --count 200 --machine grbl-laser --feed 1500 --travel-feed 4000 --arcs --chord-tolerance 0.05 -o feeds.gcode", 0, "cd31b63666d3b2f83cef5623628a10f52a98d6d4b2cff67dde4b941d8572db3e"),
    ("fill --shape ring:0.5 --n-offset 2 --count 150 --machine grbl-laser --hatch 0.3:45 --hatch-only -o engrave.gcode", 0, "455400d420a0f48fa16af24660e1c4fab8a5ed507d8cc7112696c7b54d567b71"),
    ("fill --region rect:500:300 --count 200 --fit --margin 10 -o big.gcode", 0, "b4145a72cc97eee3f13dbc391aade4ba5477ac1746ae8199f47d4e8d084a4aae"),
    ("fill --count 300 --hatch 0.5:30 --cross-hatch --min-feature 0.6 --page a4 --fit -o hatched.svg", 0, "dea3d2e1f9ae5db85f1e06d4b38adf77cc85dad244bcb039e5f19f80025c502f"),
    ("machines show grbl-laser", 0, "dcf9a4049517731c67d26649b17a20977b6b715fd4306b1938b459504f69aaed"),
    ("fill --count 200 --machine laser.toml -o profile.gcode", 0, "57e3df112b9e8d5a4e261e41dd9b169b0feae7042b2addd40f208fcb8514434d"),
    // line
    ("line --count 300 -o line.svg", 0, "63a2587c5cd7fbafdae4f83c08afd47c68ad3135f6e465abafb0fbb800154de9"),
    ("line --render dashes --periodic --count 300 --boundary -o dashes.svg", 0, "3b50b989549ba4fcdd7c687a8a694b8a9cb96b6a80a9271604e88b0d66029d72"),
    ("line --render bars --bar-height 40 --count 300 --palette {P5} --background fefae0 --pixels 300 -o bars.png", 0, "83b34a8aae1a83bda366128a13aafd8929abcf0305619c9d92537aca6e4cbef5"),
    ("line --c 1.4 --count 3000 --periodic --render zoom -o zoom.svg", 0, "a786767ec8761f9fe79f8be0e2a0db8427b7df87a2d0535d6948f9e9b614bf7a"),
    ("line --count 300 --style filled --palette 1d3557,e63946 --color-by cycle -o line-filled.svg", 0, "e91277648a49c13453274c1691b063ff6ad2e19b4b749aca569788563d15a852"),
    ("line --count 300 -o line.json", 0, "1ffea4a9c25cc2219d09ccb78a4d76ed1ff5d69c8cc2da6d6f9f436551e03ce9"),
    ("line --dimension 0.7 --fill 0.6 --gap 0.1 --sampler reference -o line.csv", 0, "e0a1c30ec022dc97647d73dea32c70d102b43a11e2e863e2d8476cd3bc3cb975"),
    ("line --count 300 --format digest --sampler reference -o line.txt", 0, "9f02f235903b94f99c8b52d4f5793f7ce4433df3ee2ae75e1236ac7de36b076b"),
    ("line --count 300 --render bars --machine grbl-laser --hatch 0.5 -o bars.gcode", 0, "415d060c09e687d6224371393e3039c8d43a9dba5b344a6d843c299da0212d14"),
    ("line --count 300 --palette 1d3557,e63946 --color-by cycle --render bars --layers colours --machine grbl-servo-pen -o line-pens.gcode", 0, "d5db5564c7043a2d4dad7bacbb259c37553102a2c45c49161a708ba252940091"),
    // territory
    ("territory --sites 3 --points 1500 --seed 3 -o boundaries.svg", 0, "e816a5e00ff7f3debfb5cff681b9c0bfe51cc4a6c4cf1304238b109e1d9bf8ee"),
    ("territory --sites 3 --points 1500 --seed 3 --render cells --boundary -o cells.svg", 0, "2cfd410b9fe687701fd6ec880ce194043c9dda4884f523f53048f9daf7aa44c6"),
    ("territory --sites 3 --points 1500 --seed 3 --render filled --pixels 200 -o territory.png", 0, "05d8a5aeabd9fe94cf6baf0e826a7c0e884ed6f79aca060103eaf49e3f98e4f1"),
    ("territory --sites 3 --points 1500 --seed 3 --machine grbl-servo-pen -o territory.gcode", 0, "8e1572e9793bf5443a9666e9181ff9b2ec0c42821a7cf8ef8d4a62351461f1ce"),
    ("territory --sites 4 --points 1500 --uniform --region circle:80 -o territory.json", 0, "aad7e3fbcf439c0cdba8ec4c29e96d9eb5873b43ccdb1da76f8ad2fc92292f8e"),
    ("territory --sites-from fill.json --sites 4 --render shapes -o coloured.svg", 0, "c79ea13d3852c3404b539a80bfcb337e2cb4ba7ca9fa8638c28213de9425c0c7"),
    ("territory --site 50,50 --site 150,150 --points 800 --color 0.1,0.8,0.9:0.01,0,-0.02 --render filled -o hsb.svg", 0, "4878d956f746e63f5ad98be36f5229892d814b4f9bd7645b28ebd075f32bf8c9"),
    ("territory --sites 6 --points 1500 --render filled --palette {P5} --color-by size --background fdf6e3 --pixels 200 -o territory-palette.png", 0, "e4689a01f011d434132f3b1afd6ffb076bfd5bc3be959bf6b26fdae4cfa6be1b"),
    // tile
    ("tile -q -o tile.svg", 0, "08577790c47bc8a8c92055c571cbc8ccecae2b598d89049fa7eaf8a0b69dc4fa"),
    ("tile -q --layout mosaic --rows 3 -o mosaic.svg", 0, "6d83a8e788ff7a987f3facefef49e4031693d31772f1cdc1d5522b0c640f41ae"),
    ("tile -q --layout planet --rows 3 --tries 3000 --style filled --pixels 200 -o planet.png", 0, "e5f1e038abceed8ef87cf20cfa92e815bf21d99487c1e19cc9311fd50b87e66c"),
    ("tile -q --render voronoi --tries 3000 --style filled -o tile-cobbles.svg", 0, "3f9587ebeb85ff6e83a81052f5569a8c2e51dea62f0cfb1d41946c0bed00c108"),
    ("tile -q --tries 3000 -o tile.json", 0, "944afa512f8bfad169d8e54d3ea894995e88afca75042856bc281cfd63cd4b5c"),
    ("tile -q --tries 3000 --machine z-lift-pen -o tile.gcode", 0, "a73e179b0637ff0d5faa5d383a0323a2a93eebba185c66f61b60f872ff7d6676"),
    ("tile -q --tries 3000 --render voronoi --relief cone --pixels 160 -o tile-relief.png", 0, "cbaef63968704711ce7ed612f1dd115182dd445bfad473d2accaedf833bce85f"),
    ("tile -q --tries 3000 --palette 1d3557,e63946 --color-by random --layers colours -o tile-pens.svg", 0, "5ca2d76a9fd8c87c5dea835df5bf6f95eefb91775f50dea23bf0dfe231d49580"),
    // stats and machines
    ("stats zeta --c 1.3 --n-offset 1", 0, "2f1c2422e62b57f6bd209e33494dd7709cb1fd4711db092819ca41c8adeeae80"),
    ("stats zeta --c 1.3 --n-offset 2.5 --json", 0, "d7fd23fb0c8fec6795f4423eab1c8e21fe1a8d04589041a445ffdb1b569d1c2d"),
    ("stats gasket --c 1.3 --n-offset 1 --n 100 --json", 0, "eef2b379173ec8c164dbfe48dcbe2b5bf8298ebb5c714a08158c24b57347c89e"),
    ("stats trials --c 1.2,1.3 --count 500 --runs 2 -o trials.svg", 0, "0f47080b0bf25a642e77ca9056fb1cb8375bc9270af762bb4139b5b0f51bc78e"),
    ("stats trials --c 1.3 --count 500 --runs 2 --sampler fast -o trials.csv", 0, "4ebf8308fbe7d7066db03523a7b24321e3a0e3b2b995b998748433149ebf6aa6"),
    ("stats trials --c 1.3 --count 300 --json", 0, "408f2e71406337c808dda802f2a630250114d21236c2779a7350e2d9a520a0c6"),
    ("stats halting --c-from 1.3 --c-to 1.5 --c-step 0.1 --runs 4 --count 20 --max-trials 20000 --threads 1 -q -o halting.csv", 0, "71532945aad294ed38622e0cf3dd69c0beedfa9f07b8807aad6ac50ff3bdc4b8"),
    ("stats halting --c-from 1.3 --c-to 1.5 --c-step 0.1 --runs 4 --count 20 --max-trials 20000 --threads 1 -q -o halting.svg", 0, "1aecbc85189b293261b4fae1cb3ddd392d25be54668345642ebb2475ce885431"),
    ("stats dimension fill.json --json", 0, "61fd28459b6847395a06950fafd7db18cd057c4d6b3cad1f76943f875af8bfe4"),
    ("machines list", 0, "56adf9a6fae628a7b9f5154cb1adcd1de54e34f8bc9505cd50a01ed5519dc39c"),
];

/// An SVG outline for `--region svg:`: a rounded square with a hole.
const OUTLINE: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="100mm" viewBox="0 0 120 100">
<path d="M 10 0 H 110 Q 120 0 120 10 V 90 Q 120 100 110 100 H 10 Q 0 100 0 90 V 10 Q 0 0 10 0 Z M 40 30 H 80 V 70 H 40 Z"/>
</svg>
"#;

/// The command's words (`{P5}` expanded).
fn words(command: &str) -> Vec<String> {
    command.replace("{P5}", P5).split_whitespace().map(String::from).collect()
}

/// Runs one command in `dir`: its exit code and the SHA-256 (hex) of what it wrote.
fn run(dir: &Path, command: &str) -> (i32, String, String) {
    let args = words(command);
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = zf(dir, &refs);
    let target = args.iter().position(|a| a == "-o").and_then(|i| args.get(i + 1));
    let bytes = match target {
        Some(path) if path != "-" => std::fs::read(dir.join(path)).unwrap_or_default(),
        _ => out.stdout.clone(),
    };
    if command.starts_with("machines show") {
        // Kept for the entry that reads a profile file.
        std::fs::write(dir.join("laser.toml"), &out.stdout).unwrap_or_else(|e| panic!("laser.toml: {e}"));
    }
    let hex: String = Sha256::digest(&bytes).iter().map(|b| format!("{b:02x}")).collect();
    (out.code, hex, out.stderr)
}

/// Runs the whole corpus in a fresh folder; the entries that differ from the table.
fn mismatches(corpus: &[(&str, i32, &str)]) -> Vec<String> {
    let dir = tmp();
    std::fs::write(dir.path().join("outline.svg"), OUTLINE).unwrap_or_else(|e| panic!("outline.svg: {e}"));
    let mut bad = Vec::new();
    for &(command, code, sha) in corpus {
        let (got_code, got, stderr) = run(dir.path(), command);
        println!("    (\"{command}\", {got_code}, \"{got}\"),");
        if got_code != code || got != sha {
            bad.push(format!(
                "{command}: exit {got_code} (want {code}), sha256 {got} (want {sha}) {stderr}"
            ));
        }
    }
    bad
}

#[test]
fn corpus_outputs_are_unchanged() {
    assert!(CORPUS.len() >= 40, "the corpus holds at least 40 commands");
    let bad = mismatches(CORPUS);
    assert!(
        bad.is_empty(),
        "{} of {} outputs changed:\n{}",
        bad.len(),
        CORPUS.len(),
        bad.join("\n")
    );
}

#[test]
fn corpus_check_fails_on_a_changed_output() {
    // The control first: an unchanged command matches its pinned digest...
    let (command, code, sha) = CORPUS[0];
    assert!(mismatches(&[(command, code, sha)]).is_empty(), "the control matches");
    // ...and the same command with one parameter changed does not.
    let changed = command.replace("--count 300", "--count 301");
    assert_ne!(changed, command);
    assert_eq!(mismatches(&[(&changed, code, sha)]).len(), 1, "a changed output is reported");
    // A wrong exit code is reported too.
    assert_eq!(mismatches(&[(command, 3, sha)]).len(), 1, "a changed exit code is reported");
}
