//! The board: a virtual-time clock, stack painting, and the memory figures from the linker.
//!
//! - Clock: SysTick, clocked by the core clock, free-running over its 24 bits. Under
//!   `qemu-system-arm -icount shift=0` one guest instruction advances virtual time by 1 ns and
//!   the lm3s6965's reset system clock is 12.5 MHz (QEMU: 200 MHz PLL output divided by
//!   SYSDIV + 1 = 16), so one tick is 80 instructions and the count is deterministic.
//!   [`Board::calibrate`] measures that ratio on a loop of known length instead of trusting
//!   it. A [`Clock`] extends the counter in software: it must be read at least once every
//!   2^24 ticks (1.3e9 instructions), which the engine's steps are far below.
//! - Stack painting: at start-up every word between the end of the statics (`__sheap`) and the
//!   current stack pointer is set to [`PAINT`]; the deepest word changed since is the stack's
//!   high-water mark.
//! - Memory: static RAM is `.data + .bss + .uninit` (`__sheap - ORIGIN(RAM)`); flash is the
//!   vector table, code, read-only data and the initial values of `.data`, and its budget the
//!   linker's `_flash_budget` (`memory.x`, where the link fails beyond it).

use core::ptr::addr_of;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;

/// Instructions in the calibration loop: `cortex_m::asm::delay(n)` runs `n + 1` iterations
/// of `subs; bne`.
pub const CALIBRATION_INSTRUCTIONS: u64 = 2 * (CALIBRATION_LOOPS as u64 + 1);
const CALIBRATION_LOOPS: u32 = 4_000_000;
/// The word painted on the unused stack.
pub const PAINT: u32 = 0xC0FF_EE11;
/// Start of RAM on the LM3S6965.
const RAM_ORIGIN: usize = 0x2000_0000;
/// Start of flash on the LM3S6965.
const FLASH_ORIGIN: usize = 0x0000_0000;

extern "C" {
    static __sheap: u32;
    static _stack_start: u32;
    static __sidata: u32;
    static __sdata: u32;
    static __edata: u32;
    /// An absolute symbol: its address is the flash budget in bytes.
    static _flash_budget: u32;
}

/// The board's resources in use: SysTick, free-running.
pub struct Board {
    _syst: SYST,
}

impl Board {
    /// Paints the stack and starts SysTick.
    pub fn init(mut syst: SYST) -> Board {
        paint_stack();
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(0x00FF_FFFF);
        syst.clear_current();
        syst.enable_counter();
        Board { _syst: syst }
    }

    /// Paints the unused stack again, so that [`Board::memory`] measures from here on.
    pub fn repaint(&self) {
        paint_stack();
    }

    /// A clock counting ticks from now.
    pub fn clock(&self) -> Clock {
        Clock {
            last: SYST::get_current(),
            total: 0,
        }
    }

    /// SysTick ticks spent on [`CALIBRATION_INSTRUCTIONS`] instructions.
    pub fn calibrate(&self) -> u64 {
        let mut clock = self.clock();
        cortex_m::asm::delay(CALIBRATION_LOOPS);
        clock.now()
    }

    /// The memory figures so far.
    pub fn memory(&self) -> Memory {
        let sheap = addr_of!(__sheap) as usize;
        let top = addr_of!(_stack_start) as usize;
        let data = (addr_of!(__edata) as usize).saturating_sub(addr_of!(__sdata) as usize);
        let flash = (addr_of!(__sidata) as usize).saturating_sub(FLASH_ORIGIN) + data;
        Memory {
            static_ram: sheap - RAM_ORIGIN,
            stack: top - deepest_changed_word(sheap, top),
            flash,
            flash_budget: addr_of!(_flash_budget) as usize,
        }
    }
}

/// Memory use in bytes.
pub struct Memory {
    /// `.data + .bss + .uninit`.
    pub static_ram: usize,
    /// Stack high-water mark.
    pub stack: usize,
    /// Flash in use.
    pub flash: usize,
    /// Flash an image may use (`_flash_budget` in `memory.x`).
    pub flash_budget: usize,
}

/// Ticks since the clock was made.
pub struct Clock {
    last: u32,
    total: u64,
}

impl Clock {
    /// Ticks since the clock was made (SysTick counts down; the difference is taken modulo
    /// 2^24, so each call must come within 2^24 ticks of the previous one).
    pub fn now(&mut self) -> u64 {
        let cur = SYST::get_current();
        self.total += u64::from(self.last.wrapping_sub(cur) & 0x00FF_FFFF);
        self.last = cur;
        self.total
    }
}

/// Paints every word from the end of the statics to just below the current stack pointer.
#[inline(never)]
#[allow(unsafe_code)]
fn paint_stack() {
    let start = addr_of!(__sheap) as usize;
    let end = (cortex_m::register::msp::read() as usize).saturating_sub(64) & !3;
    let mut p = start;
    while p < end {
        // SAFETY: [__sheap, sp - 64) is RAM that no static and no live stack frame uses
        // (cortex-m-rt places the statics below __sheap and the stack grows down from the top).
        unsafe { (p as *mut u32).write_volatile(PAINT) };
        p += 4;
    }
}

/// The lowest address in `[start, top)` whose word is no longer the paint.
#[allow(unsafe_code)]
fn deepest_changed_word(start: usize, top: usize) -> usize {
    let mut p = start;
    // SAFETY: [start, top) is this board's RAM; reading a word of it is always defined.
    while p < top && unsafe { (p as *const u32).read_volatile() } == PAINT {
        p += 4;
    }
    p
}
