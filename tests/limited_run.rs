//! The child-process runner of the hostile-input tests: the real binary
//! under resource limits set in the child (`setrlimit`), with a wall-clock
//! kill for inputs that block rather than compute, both output streams read
//! as they come (a full pipe would block the child).

#![cfg(unix)]

use std::io::Read;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A resource (`libc::RLIMIT_*`) and its limit.
pub type Limit = (libc::__rlimit_resource_t, u64);

/// How a run ended.
pub struct Finished {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `hscene args` in `dir` under `limits`, killed after `wall`. Panics
/// if it blocks past `wall`, is killed by a signal, exits other than 0, 1
/// or 2, or panics: hostile input must end in a clear message.
pub fn run_hscene(dir: &Path, args: &[&str], limits: &[Limit], wall: Duration) -> Finished {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_hscene"));
    cmd.args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let limits = limits.to_vec();
    // SAFETY: setrlimit is async-signal-safe and touches only the child.
    unsafe {
        cmd.pre_exec(move || {
            for &(resource, value) in &limits {
                let r = libc::rlimit {
                    rlim_cur: value as libc::rlim_t,
                    rlim_max: value as libc::rlim_t,
                };
                if libc::setrlimit(resource, &r) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
            }
            Ok(())
        });
    }
    let mut child = cmd.spawn().expect("the binary starts");
    let (out, err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let readers = (read_all(out), read_all(err));
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > wall {
            let _ = child.kill();
            panic!("hscene {args:?} blocked past the wall-clock limit");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let stdout = String::from_utf8_lossy(&readers.0.join().unwrap()).into_owned();
    let stderr = String::from_utf8_lossy(&readers.1.join().unwrap()).into_owned();
    let code = status.code().unwrap_or_else(|| {
        panic!("hscene {args:?} was killed ({status}) under the limits; stderr:\n{stderr}")
    });
    assert!(
        matches!(code, 0..=2) && !stderr.contains("panicked"),
        "hscene {args:?} exited {code}; stderr:\n{stderr}"
    );
    Finished {
        code,
        stdout,
        stderr,
    }
}

fn read_all(mut stream: impl Read + Send + 'static) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = stream.read_to_end(&mut s);
        s
    })
}
