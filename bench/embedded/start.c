/* The start of the bare-metal program bench/embedded/run counts instructions with (MPS2 AN386,
 * Cortex-M4): the vector table, the FPU enabled, `run` (the generated caller), a semihosting
 * exit. `mark` is called before each call and once at the end: the count's boundaries. */
typedef void (*handler)(void);
/* The initial stack pointer, from link.ld; declared a function so that the table needs no
 * cast between object and function pointers. */
extern void __stack_top(void);
void reset(void);
void run(void);
void mark(void);
__attribute__((section(".vectors"), used)) const handler vectors[2] = {__stack_top, reset};

__attribute__((noinline)) void mark(void) {
    __asm__ volatile("");
}

void reset(void) {
    *(volatile unsigned *)0xE000ED88 |= 0xFu << 20; /* CPACR: CP10 and CP11, the FPU */
    __asm__ volatile("dsb\n isb");
    run();
    mark();
    {
        register unsigned r0 __asm__("r0") = 0x18;    /* SYS_EXIT */
        register unsigned r1 __asm__("r1") = 0x20026; /* ADP_Stopped_ApplicationExit */
        __asm__ volatile("bkpt 0xab" : : "r"(r0), "r"(r1) : "memory");
    }
    for (;;) {
    }
}
