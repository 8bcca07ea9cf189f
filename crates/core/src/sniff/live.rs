//! Packets captured live from a network interface, through libpcap: a BPF filter keeps the
//! Modbus ports, and each packet comes out as a capture file's would.
//!
//! libpcap is loaded when a live capture opens, not linked: linked, it and the libraries it
//! pulls in (dbus, systemd, gcrypt, lzma, zstd...) were loaded by every mbtool process,
//! which cost each one-shot command more than its own work. Building needs no libpcap
//! either; running `sniff --interface` needs it installed.
//!
//! Calling a C library is the one place mbtool needs `unsafe`: each call says what makes it
//! sound, and nothing outside this module sees a pointer.
#![allow(unsafe_code)]

use std::ffi::{c_char, c_int, c_long, c_uint, c_void, CStr, CString};
use std::time::{Duration, Instant};

use libloading::Library;
use thiserror::Error;

use super::capture::Packet;

/// Why an interface cannot be captured from.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum LiveError {
    /// Capturing needs privileges the process lacks.
    #[error("capturing on {0} needs privileges: run as root, or once: sudo setcap cap_net_raw,cap_net_admin=eip \"$(command -v mbtool)\"")]
    Permission(String),
    /// No interface has the name.
    #[error("there is no interface {name}: the interfaces here are {here}")]
    NoInterface {
        /// The name given.
        name: String,
        /// The interfaces that exist.
        here: String,
    },
    /// libpcap is not installed.
    #[error("live capture needs libpcap ({0}): install libpcap0.8 (Debian, Ubuntu), libpcap (Fedora, Arch) or Npcap (Windows), or record with tcpdump and give --input FILE")]
    NoLibrary(String),
    /// Anything else libpcap says.
    #[error("cannot capture on {interface}: {message}")]
    Pcap {
        /// The interface.
        interface: String,
        /// libpcap's words.
        message: String,
    },
}

/// The names libpcap goes by, most specific first.
#[cfg(target_os = "windows")]
const LIBRARY_NAMES: &[&str] = &["wpcap.dll"];
#[cfg(target_os = "macos")]
const LIBRARY_NAMES: &[&str] = &["libpcap.A.dylib", "libpcap.dylib"];
#[cfg(not(any(target_os = "windows", target_os = "macos")))]
const LIBRARY_NAMES: &[&str] = &["libpcap.so.1", "libpcap.so.0.8", "libpcap.so"];

/// libpcap's `PCAP_ERRBUF_SIZE`.
const ERRBUF_SIZE: usize = 256;
/// `pcap_activate` status codes that mean something to the user.
const PCAP_ERROR_NO_SUCH_DEVICE: c_int = -5;
const PCAP_ERROR_PERM_DENIED: c_int = -8;

#[repr(C)]
struct Timeval {
    tv_sec: c_long,
    #[cfg(target_os = "macos")]
    tv_usec: i32,
    #[cfg(not(target_os = "macos"))]
    tv_usec: c_long,
}

#[repr(C)]
struct PacketHeader {
    ts: Timeval,
    caplen: u32,
    len: u32,
}

#[repr(C)]
struct BpfProgram {
    bf_len: c_uint,
    bf_insns: *mut c_void,
}

#[repr(C)]
struct Interface {
    next: *mut Interface,
    name: *mut c_char,
    description: *mut c_char,
    addresses: *mut c_void,
    flags: u32,
}

type Handle = *mut c_void;

/// The functions of libpcap a capture uses, looked up once.
struct Functions {
    create: unsafe extern "C" fn(*const c_char, *mut c_char) -> Handle,
    set_snaplen: unsafe extern "C" fn(Handle, c_int) -> c_int,
    set_immediate_mode: unsafe extern "C" fn(Handle, c_int) -> c_int,
    activate: unsafe extern "C" fn(Handle) -> c_int,
    setnonblock: unsafe extern "C" fn(Handle, c_int, *mut c_char) -> c_int,
    compile: unsafe extern "C" fn(Handle, *mut BpfProgram, *const c_char, c_int, u32) -> c_int,
    setfilter: unsafe extern "C" fn(Handle, *mut BpfProgram) -> c_int,
    freecode: unsafe extern "C" fn(*mut BpfProgram),
    datalink: unsafe extern "C" fn(Handle) -> c_int,
    next_ex: unsafe extern "C" fn(Handle, *mut *mut PacketHeader, *mut *const u8) -> c_int,
    geterr: unsafe extern "C" fn(Handle) -> *const c_char,
    statustostr: unsafe extern "C" fn(c_int) -> *const c_char,
    close: unsafe extern "C" fn(Handle),
    findalldevs: unsafe extern "C" fn(*mut *mut Interface, *mut c_char) -> c_int,
    freealldevs: unsafe extern "C" fn(*mut Interface),
}

/// libpcap, loaded: the library stays loaded as long as its functions may be called.
struct Pcap {
    functions: Functions,
    _library: Library,
}

impl Pcap {
    fn load() -> Result<Pcap, LiveError> {
        let mut tried = Vec::new();
        for name in LIBRARY_NAMES {
            // SAFETY: libpcap's initialisers only set up its own state.
            match unsafe { Library::new(name) } {
                Ok(library) => return Self::from_library(library),
                Err(error) => tried.push(error.to_string()),
            }
        }
        Err(LiveError::NoLibrary(tried.join("; ")))
    }

    fn from_library(library: Library) -> Result<Pcap, LiveError> {
        macro_rules! function {
            ($name:literal) => {
                // SAFETY: the type is the one libpcap's header gives the function.
                *unsafe { library.get($name) }.map_err(|e| LiveError::NoLibrary(e.to_string()))?
            };
        }
        let functions = Functions {
            create: function!(b"pcap_create\0"),
            set_snaplen: function!(b"pcap_set_snaplen\0"),
            set_immediate_mode: function!(b"pcap_set_immediate_mode\0"),
            activate: function!(b"pcap_activate\0"),
            setnonblock: function!(b"pcap_setnonblock\0"),
            compile: function!(b"pcap_compile\0"),
            setfilter: function!(b"pcap_setfilter\0"),
            freecode: function!(b"pcap_freecode\0"),
            datalink: function!(b"pcap_datalink\0"),
            next_ex: function!(b"pcap_next_ex\0"),
            geterr: function!(b"pcap_geterr\0"),
            statustostr: function!(b"pcap_statustostr\0"),
            close: function!(b"pcap_close\0"),
            findalldevs: function!(b"pcap_findalldevs\0"),
            freealldevs: function!(b"pcap_freealldevs\0"),
        };
        Ok(Pcap {
            functions,
            _library: library,
        })
    }

    /// The names of the interfaces libpcap can capture on, joined for a message.
    fn interfaces(&self) -> String {
        let mut errbuf = [0 as c_char; ERRBUF_SIZE];
        let mut first: *mut Interface = std::ptr::null_mut();
        // SAFETY: libpcap fills `first` with a list it owns until freealldevs.
        if unsafe { (self.functions.findalldevs)(&mut first, errbuf.as_mut_ptr()) } != 0 {
            return String::new();
        }
        let mut names = Vec::new();
        let mut at = first;
        while !at.is_null() {
            // SAFETY: `at` is an element of the list, its name a C string or null.
            let interface = unsafe { &*at };
            if !interface.name.is_null() {
                let name = unsafe { CStr::from_ptr(interface.name) }.to_string_lossy();
                if name != "any" && !name.contains("nflog") && !name.contains("nfqueue") {
                    names.push(name.into_owned());
                }
            }
            at = interface.next;
        }
        // SAFETY: the list came from findalldevs and is freed once.
        unsafe { (self.functions.freealldevs)(first) };
        names.join(", ")
    }
}

/// A C string libpcap returned, as text.
fn text(message: *const c_char) -> String {
    if message.is_null() {
        return String::new();
    }
    // SAFETY: libpcap returns NUL-terminated strings that live at least until the next call.
    unsafe { CStr::from_ptr(message) }
        .to_string_lossy()
        .into_owned()
}

/// A live capture.
pub struct LiveCapture {
    pcap: Pcap,
    handle: Handle,
    link: u32,
    count: u64,
}

impl Drop for LiveCapture {
    fn drop(&mut self) {
        // SAFETY: the handle came from pcap_create and is closed once.
        unsafe { (self.pcap.functions.close)(self.handle) };
    }
}

impl LiveCapture {
    /// Opens `interface`, keeping the TCP traffic of `ports`. Reads do not block (libpcap's
    /// own timeout is not kept in immediate mode): [`LiveCapture::next`] waits itself.
    pub fn open(interface: &str, ports: &[u16]) -> Result<Self, LiveError> {
        let pcap = Pcap::load()?;
        let failed = |message: String| LiveError::Pcap {
            interface: interface.to_string(),
            message,
        };
        let name = CString::new(interface).map_err(|_| failed("a name with a NUL".into()))?;
        let mut errbuf = [0 as c_char; ERRBUF_SIZE];
        let f = &pcap.functions;
        // SAFETY: the name and the error buffer outlive the call.
        let handle = unsafe { (f.create)(name.as_ptr(), errbuf.as_mut_ptr()) };
        if handle.is_null() {
            return Err(classify(&pcap, interface, &text(errbuf.as_ptr())));
        }
        let mut capture = LiveCapture {
            link: 0,
            count: 0,
            handle,
            pcap,
        };
        let f = &capture.pcap.functions;
        // SAFETY: the handle is open and not yet activated, as these calls need.
        let status = unsafe {
            (f.set_snaplen)(handle, 65535);
            (f.set_immediate_mode)(handle, 1);
            (f.activate)(handle)
        };
        if status < 0 {
            let message = match status {
                PCAP_ERROR_PERM_DENIED => return Err(LiveError::Permission(interface.into())),
                PCAP_ERROR_NO_SUCH_DEVICE => "No such device exists".to_string(),
                // SAFETY: the handle is open.
                _ => match text(unsafe { (f.geterr)(handle) }) {
                    empty if empty.is_empty() => text(unsafe { (f.statustostr)(status) }),
                    message => message,
                },
            };
            return Err(classify(&capture.pcap, interface, &message));
        }
        let filter = ports
            .iter()
            .map(|port| format!("tcp port {port} or udp port {port}"))
            .collect::<Vec<_>>()
            .join(" or ");
        let filter = CString::new(filter).map_err(|_| failed("a bad filter".into()))?;
        let mut program = BpfProgram {
            bf_len: 0,
            bf_insns: std::ptr::null_mut(),
        };
        // SAFETY: the handle is active; the program is freed once it is set.
        let filtered = unsafe {
            (f.compile)(handle, &mut program, filter.as_ptr(), 1, 0xFFFF_FFFF) == 0 && {
                let set = (f.setfilter)(handle, &mut program) == 0;
                (f.freecode)(&mut program);
                set
            }
        };
        // SAFETY: as above.
        let nonblocking = unsafe { (f.setnonblock)(handle, 1, errbuf.as_mut_ptr()) } == 0;
        if !filtered || !nonblocking {
            return Err(failed(text(unsafe { (f.geterr)(handle) })));
        }
        // SAFETY: the handle is active.
        capture.link = u32::try_from(unsafe { (f.datalink)(handle) }).unwrap_or(u32::MAX);
        Ok(capture)
    }

    /// The link type of the interface's packets.
    pub fn link(&self) -> u32 {
        self.link
    }

    /// The next packet, handed to `each`; `Ok(false)` when none came within `wait`.
    pub fn next(&mut self, wait: Duration, each: impl FnOnce(Packet)) -> Result<bool, LiveError> {
        let until = Instant::now() + wait;
        let f = &self.pcap.functions;
        loop {
            let mut header: *mut PacketHeader = std::ptr::null_mut();
            let mut data: *const u8 = std::ptr::null();
            // SAFETY: the handle is active; libpcap points both at its own buffer, valid
            // until the next call on the handle.
            let status = unsafe { (f.next_ex)(self.handle, &mut header, &mut data) };
            match status {
                1 if !header.is_null() && !data.is_null() => {
                    self.count += 1;
                    // SAFETY: as above; `caplen` bytes are there.
                    let header = unsafe { &*header };
                    let captured = usize::try_from(header.caplen).unwrap_or(0);
                    let data = unsafe { std::slice::from_raw_parts(data, captured) };
                    let seconds = u64::try_from(header.ts.tv_sec).unwrap_or(0);
                    let micros = u64::try_from(header.ts.tv_usec).unwrap_or(0);
                    each(Packet {
                        number: self.count,
                        time_us: seconds * 1_000_000 + micros,
                        link: self.link,
                        data,
                        original_len: header.len,
                    });
                    return Ok(true);
                }
                0 | 1 if Instant::now() < until => std::thread::sleep(Duration::from_millis(2)),
                0 | 1 => return Ok(false),
                _ => {
                    return Err(LiveError::Pcap {
                        interface: String::new(),
                        // SAFETY: the handle is open.
                        message: text(unsafe { (f.geterr)(self.handle) }),
                    });
                }
            }
        }
    }
}

/// What libpcap's message means for the user.
fn classify(pcap: &Pcap, interface: &str, message: &str) -> LiveError {
    let lower = message.to_lowercase();
    if lower.contains("permission") || lower.contains("not permitted") {
        return LiveError::Permission(interface.to_string());
    }
    if lower.contains("no such device") {
        return LiveError::NoInterface {
            name: interface.to_string(),
            here: pcap.interfaces(),
        };
    }
    LiveError::Pcap {
        interface: interface.to_string(),
        message: message.to_string(),
    }
}
