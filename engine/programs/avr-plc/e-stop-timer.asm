.equ Run_R=4
.equ Run_B=Bit0
.equ Direct_R=4
.equ Direct_B=Bit1
.equ E_Stop_R=6
.equ E_Stop_B=Bit7
.dseg
PLC_Timer_Top: ; PLC Timers
E_Stop_Timer:    .byte 2
.cseg
; The seed's timer example: Run and Direct through a 1 s TOF drive E_Stop
; Run  Direct    E_Stop
;--| |--| |--[TOF]--( )-|
.db Load_A,Run_R,Run_B,0
.db And_A,Direct_R,Direct_B,0
.db TOF,LOW(E_Stop_Timer),LOW(1000/Scan),HIGH(1000/Scan)
.db Coil_A,E_Stop_R,E_Stop_B,0
.db End_PLC,0,0,0
