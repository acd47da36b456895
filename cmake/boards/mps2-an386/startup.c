/* The Cortex-M vector table: the initial stack pointer and the reset handler, which turns the
   FPU on (the code is built for hardware floating point) and enters newlib's semihosting
   start-up (rdimon), which clears .bss, runs constructors and calls main(). */
extern void _start(void);
extern unsigned __stack_top;

static void hang(void) {
  for (;;) {
  }
}

static void reset(void) {
  *(volatile unsigned*)0xE000ED88u |= 0xFu << 20; /* CPACR: CP10 and CP11, full access */
  __asm volatile("dsb\n\tisb");
  _start();
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))&__stack_top, reset, hang, hang, hang, hang, hang, 0, 0, 0, 0,
    hang, hang, 0, hang, hang};
