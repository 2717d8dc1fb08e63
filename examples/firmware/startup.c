/* Start-up for a Cortex-M4F: the vector table, the FPU switched on, then the C library's own
 * start (newlib's crt0 for semihosting: zeroed .bss, argc/argv from the host, main, exit). */
#include <stdint.h>

extern uint32_t __stack_top;
extern void _start(void);

void Reset_Handler(void);
void Default_Handler(void);

void Reset_Handler(void) {
  /* CPACR: full access to coprocessors 10 and 11, the FPU, before any float instruction. */
  *(volatile uint32_t*)0xE000ED88u |= 0xFu << 20;
  __asm volatile("dsb\n\tisb" ::: "memory");
  _start();
  for (;;) {
  }
}

void Default_Handler(void) {
  for (;;) {
  }
}

/* Initial stack pointer, reset, then the 14 system exceptions: none is expected here. */
__attribute__((section(".vectors"), used)) void* const vectors[16] = {
    &__stack_top,    (void*)Reset_Handler, (void*)Default_Handler, (void*)Default_Handler,
    (void*)Default_Handler, (void*)Default_Handler, (void*)Default_Handler, 0,
    0,               0,                    0,                      (void*)Default_Handler,
    (void*)Default_Handler, 0,             (void*)Default_Handler, (void*)Default_Handler};
