/*
 * A stand-in for the RS-485 features of a serial driver, loaded with LD_PRELOAD into
 * mbtool by tests/cli/rs485.rs. A pseudo-terminal has neither the kernel's RS-485 mode
 * nor an RTS line; this shim answers their ioctls as a UART driver would and writes
 * every one of them, and every byte written to or read from a pseudo-terminal, to the
 * file named by RS485_SHIM_LOG, one line each with CLOCK_MONOTONIC in nanoseconds:
 *
 *   <ns> rs485 <flags> <delay before> <delay after>   TIOCSRS485
 *   <ns> rts <0|1>                                    RTS changed (TIOCMBIS, TIOCMBIC, TIOCMSET)
 *   <ns> write <n>                                    n bytes written to a pty
 *   <ns> drain                                        tcdrain returned
 *   <ns> read <n>                                     n bytes read from a pty
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <linux/serial.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

static struct serial_rs485 rs485_now;
static int modem_lines = 0;

static ssize_t real_write(int fd, const void *buf, size_t n) {
    static ssize_t (*real)(int, const void *, size_t);
    if (!real) real = dlsym(RTLD_NEXT, "write");
    return real(fd, buf, n);
}

static void record(const char *format, ...) {
    const char *path = getenv("RS485_SHIM_LOG");
    if (!path) return;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    char line[160];
    int at = snprintf(line, sizeof line, "%lld ", (long long)now.tv_sec * 1000000000LL + now.tv_nsec);
    va_list args;
    va_start(args, format);
    at += vsnprintf(line + at, sizeof line - at, format, args);
    va_end(args);
    line[at++] = '\n';
    int log = open(path, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (log < 0) return;
    real_write(log, line, at);
    close(log);
}

static int is_pty(int fd) {
    char link[64], target[64];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    ssize_t n = readlink(link, target, sizeof target - 1);
    if (n <= 0) return 0;
    target[n] = 0;
    return strncmp(target, "/dev/pts/", 9) == 0 || strcmp(target, "/dev/ptmx") == 0;
}

static void set_modem_lines(int lines) {
    if ((lines ^ modem_lines) & TIOCM_RTS) record("rts %d", (lines & TIOCM_RTS) ? 1 : 0);
    modem_lines = lines;
}

int ioctl(int fd, unsigned long request, ...) {
    static int (*real)(int, unsigned long, void *);
    if (!real) real = dlsym(RTLD_NEXT, "ioctl");
    va_list args;
    va_start(args, request);
    void *arg = va_arg(args, void *);
    va_end(args);
    switch (request) {
    case TIOCGRS485:
        memcpy(arg, &rs485_now, sizeof rs485_now);
        return 0;
    case TIOCSRS485:
        memcpy(&rs485_now, arg, sizeof rs485_now);
        record("rs485 %u %u %u", rs485_now.flags, rs485_now.delay_rts_before_send,
               rs485_now.delay_rts_after_send);
        return 0;
    case TIOCMGET:
        *(int *)arg = modem_lines;
        return 0;
    case TIOCMSET:
        set_modem_lines(*(int *)arg);
        return 0;
    case TIOCMBIS:
        set_modem_lines(modem_lines | *(int *)arg);
        return 0;
    case TIOCMBIC:
        set_modem_lines(modem_lines & ~*(int *)arg);
        return 0;
    default:
        return real(fd, request, arg);
    }
}

ssize_t write(int fd, const void *buf, size_t n) {
    ssize_t written = real_write(fd, buf, n);
    if (written > 0 && is_pty(fd)) record("write %zd", written);
    return written;
}

ssize_t read(int fd, void *buf, size_t n) {
    static ssize_t (*real)(int, void *, size_t);
    if (!real) real = dlsym(RTLD_NEXT, "read");
    ssize_t got = real(fd, buf, n);
    if (got > 0 && is_pty(fd)) record("read %zd", got);
    return got;
}

int tcdrain(int fd) {
    static int (*real)(int);
    if (!real) real = dlsym(RTLD_NEXT, "tcdrain");
    int result = real(fd);
    record("drain");
    return result;
}
