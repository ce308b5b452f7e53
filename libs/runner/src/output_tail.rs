//! The program's stdout and stderr, of which only the last bytes are kept. The pipes are read
//! without blocking by the thread that watches the program, between its checks: a program that
//! writes 10 MB is never blocked on a full pipe, and no reader thread can be left waiting on a
//! pipe that an escaped process still holds open.

use std::collections::VecDeque;
use std::io::{ErrorKind, Read};
use std::os::fd::AsRawFd;
use std::process::{ChildStderr, ChildStdout};
use std::time::Duration;

/// At most this much is read from one pipe per wait, so that the watcher goes back to checking
/// the clock even when a program writes as fast as it can be read. It is also what a pipe holds
/// at most (`/proc/sys/fs/pipe-max-size`, 1 MiB by default), so once the writers are dead one
/// call takes all that is left.
const READ_BUDGET: usize = 1 << 20;

/// The last `cap` bytes written to a stream.
struct Tail {
    bytes: VecDeque<u8>,
    cap: usize,
}

impl Tail {
    fn push(&mut self, data: &[u8]) {
        let data = &data[data.len().saturating_sub(self.cap)..];
        let overflow = (self.bytes.len() + data.len()).saturating_sub(self.cap);
        self.bytes.drain(..overflow);
        self.bytes.extend(data);
    }
}

/// One pipe from the program and what was kept of it; `pipe` is `None` once it reached its end.
struct Stream<R> {
    pipe: Option<R>,
    tail: Tail,
}

impl<R: Read + AsRawFd> Stream<R> {
    fn new(pipe: Option<R>, cap: usize) -> Self {
        let pipe = pipe.filter(|pipe| set_nonblocking(pipe).is_ok());
        let tail = Tail {
            bytes: VecDeque::new(),
            cap,
        };
        Self { pipe, tail }
    }

    /// Reads what is there now, up to [`READ_BUDGET`] bytes. At the end of the pipe (every
    /// writer has closed it) or on an error the pipe is closed.
    fn read_available(&mut self, buffer: &mut [u8]) {
        let Some(pipe) = &mut self.pipe else { return };
        let mut read = 0;
        let open = loop {
            if read >= READ_BUDGET {
                break true;
            }
            match pipe.read(buffer) {
                Ok(0) => break false,
                Ok(n) => {
                    self.tail.push(&buffer[..n]);
                    read += n;
                }
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(e) => break e.kind() == ErrorKind::WouldBlock,
            }
        };
        if !open {
            self.pipe = None;
        }
    }
}

fn set_nonblocking(pipe: &impl AsRawFd) -> std::io::Result<()> {
    let fd = pipe.as_raw_fd();
    // SAFETY: `fd` is the read end of a pipe we own for the lifetime of `pipe`; F_GETFL and
    // F_SETFL only change its flags. Only this process holds the read end (std opens pipes
    // close-on-exec), so non-blocking affects no one else.
    let result = unsafe {
        let flags = libc::fcntl(fd, libc::F_GETFL);
        if flags == -1 {
            -1
        } else {
            libc::fcntl(fd, libc::F_SETFL, flags | libc::O_NONBLOCK)
        }
    };
    if result == -1 {
        return Err(std::io::Error::last_os_error());
    }
    Ok(())
}

/// The program's stdout and stderr, being read.
pub(crate) struct Output {
    stdout: Stream<ChildStdout>,
    stderr: Stream<ChildStderr>,
    buffer: Vec<u8>,
}

impl Output {
    pub(crate) fn new(
        stdout: Option<ChildStdout>,
        stderr: Option<ChildStderr>,
        cap: usize,
    ) -> Self {
        Self {
            stdout: Stream::new(stdout, cap),
            stderr: Stream::new(stderr, cap),
            buffer: vec![0; 64 << 10],
        }
    }

    /// Waits up to `timeout` for either pipe to have data (or to close), then reads what is
    /// there. With both pipes closed it just sleeps: this is the watcher's tick.
    pub(crate) fn pump(&mut self, timeout: Duration) {
        let mut fds: Vec<libc::pollfd> = [
            self.stdout.pipe.as_ref().map(AsRawFd::as_raw_fd),
            self.stderr.pipe.as_ref().map(AsRawFd::as_raw_fd),
        ]
        .into_iter()
        .flatten()
        .map(|fd| libc::pollfd {
            fd,
            events: libc::POLLIN,
            revents: 0,
        })
        .collect();
        let millis = libc::c_int::try_from(timeout.as_millis()).unwrap_or(libc::c_int::MAX);
        // SAFETY: `fds` is a live, correctly sized array of pollfd for open descriptors;
        // an interrupted poll (EINTR) just returns early, and the reads below do not block.
        unsafe { libc::poll(fds.as_mut_ptr(), fds.len() as libc::nfds_t, millis) };
        self.read_both();
    }

    /// Reads what is left once the program's processes are dead: up to the end of each pipe,
    /// or until nothing more comes (a process outside the tree may still hold a pipe open).
    pub(crate) fn finish(mut self) -> (Vec<u8>, Vec<u8>) {
        self.read_both();
        (self.stdout.tail.bytes.into(), self.stderr.tail.bytes.into())
    }

    fn read_both(&mut self) {
        self.stdout.read_available(&mut self.buffer);
        self.stderr.read_available(&mut self.buffer);
    }
}
