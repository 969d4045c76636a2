//! Mutation cover of one top's generated netlist (`tb::mutation`):
//! `mutation TOP N [--seed S] [--jobs J] [--only I,J,...] [--replay-only]`.
//! Prints one line per mutant and writes `target/mutation/TOP.json` with the counts drawn, killed,
//! equivalent and surviving, and every mutant's command and verdict. `--only` judges only the listed
//! mutants of the same draw (for example the survivors of an earlier run, after new stimulus); the
//! others are written as `not judged` and the counts are over the judged ones. `--replay-only` skips
//! the equivalence check of survivors (60 s each), for a rerun of earlier survivors on new stimulus.
//! `scripts/mutation.sh` runs it.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use tb::mutation::{draw, judge, target, work_dir, write_mutants, yosys_netlist, Outcome, TOPS};

const USAGE: &str = "usage: mutation TOP N [--seed S] [--jobs J] [--only I,J,...] [--replay-only]   (TOP: rc, rc3, colour_setup, cs, opp, tex_setup; N mutants, at least 1; --only: judge only these mutant numbers, each below N)";

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut pos = Vec::new();
    let (mut seed, mut jobs) = (1u64, std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1));
    let mut only: Option<Vec<usize>> = None;
    let mut prove = true;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        if a == "--only" {
            let v = it.next().ok_or(format!("--only needs a list of mutant numbers\n{USAGE}"))?;
            let list = v.split(',').map(|w| w.trim().parse::<usize>().map_err(|_| format!("--only: '{w}' is not a mutant number\n{USAGE}"))).collect::<Result<Vec<_>, _>>()?;
            only = Some(list);
            continue;
        }
        if a == "--replay-only" {
            prove = false;
            continue;
        }
        let mut value = |name: &str| -> Result<u64, String> {
            let v = it.next().ok_or(format!("{name} needs a value\n{USAGE}"))?;
            v.parse().map_err(|_| format!("{name}: '{v}' is not a whole number\n{USAGE}"))
        };
        match a.as_str() {
            "--seed" => seed = value("--seed")?,
            "--jobs" => jobs = value("--jobs")?.max(1) as usize,
            s if s.starts_with("--") => return Err(format!("unknown option {s}\n{USAGE}")),
            s => pos.push(s.to_string()),
        }
    }
    let [top, n] = pos.as_slice() else { return Err(USAGE.into()) };
    if !TOPS.contains(&top.as_str()) {
        return Err(format!("unknown top '{top}'\n{USAGE}"));
    }
    let n: usize = n.parse().ok().filter(|&n| n > 0).ok_or(format!("N: '{n}' is not a positive number\n{USAGE}"))?;
    if let Some(bad) = only.iter().flatten().find(|&&i| i >= n) {
        return Err(format!("--only: mutant {bad} is not among the {n} drawn (0..{})\n{USAGE}", n - 1));
    }
    let judged: Vec<usize> = only.clone().unwrap_or_else(|| (0..n).collect());

    let dir = work_dir(top);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let t = target(top, &dir)?;
    println!("{top}: stimulus {}", t.stimulus);
    // The replay must pass on the generated Verilog and on the unmutated netlist that Yosys writes,
    // or every mutant would count as killed.
    t.replay(&t.verilog, &dir.join("run_generated")).map_err(|e| format!("the generated Verilog fails its own replay: {e}"))?;
    let netlist = yosys_netlist(&t, &dir)?;
    t.replay(&netlist, &dir.join("run_netlist")).map_err(|e| format!("Yosys's unmutated netlist fails the replay: {e}"))?;
    let cmds = draw(n, seed, &dir)?;
    write_mutants(&cmds, &dir)?;
    println!("{top}: {n} mutants drawn (seed {seed}), the unmutated netlist replays clean; {jobs} jobs");

    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Outcome>>> = Mutex::new(vec![None; n]);
    let t0 = std::time::Instant::now();
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                if k >= judged.len() {
                    break;
                }
                let i = judged[k];
                let o = judge(&t, &cmds[i], &dir, i, prove);
                let detail = o.detail();
                println!("{top} mutant {i:4}: {:10} {} | {detail}", o.name(), short(&cmds[i]));
                if !matches!(o, Outcome::Killed(_)) {
                    let _ = std::fs::remove_dir_all(dir.join(format!("run_{i}")));
                }
                results.lock().unwrap()[i] = Some(o);
            });
        }
    });
    let results: Vec<Option<Outcome>> = results.into_inner().unwrap();
    let count = |name: &str| results.iter().flatten().filter(|o| o.name() == name).count();
    let (killed, equivalent, surviving, errors) = (count("killed"), count("equivalent"), count("surviving"), count("error"));
    let json = serde_json::json!({
        "top": top,
        "stimulus": t.stimulus,
        "seed": seed,
        "drawn": n,
        "judged": judged.len(),
        "only": only,
        "equivalence_tried": prove,
        "killed": killed,
        "equivalent": equivalent,
        "surviving": surviving,
        "errors": errors,
        "seconds": t0.elapsed().as_secs_f64().round(),
        "mutants": results.iter().zip(&cmds).map(|(o, c)| serde_json::json!({
            "command": c,
            "outcome": o.as_ref().map_or("not judged", |o| o.name()),
            "detail": o.as_ref().map_or("", |o| o.detail()),
        })).collect::<Vec<_>>(),
    });
    let out = dir.parent().unwrap().join(format!("{top}.json"));
    std::fs::write(&out, serde_json::to_string_pretty(&json).unwrap()).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
    println!("{top}: drawn {n}, judged {}, killed {killed}, equivalent {equivalent}, surviving {surviving}, errors {errors} ({:.0} s); {}", judged.len(), t0.elapsed().as_secs_f64(), out.display());
    Ok(())
}

/// The mutation without its source locations.
fn short(cmd: &str) -> String {
    cmd.split(" -src ").next().unwrap_or(cmd).trim_start_matches("mutate ").to_string()
}
