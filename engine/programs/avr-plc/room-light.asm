; The room light (issue #51, docs/plants.md): the LAMP is on while the
; light sensor says it is DARK.
.equ DARK_R=4
.equ DARK_B=Bit0
.equ LAMP_R=5
.equ LAMP_B=Bit0
.cseg
.db Load_A,DARK_R,DARK_B,0
.db Coil_A,LAMP_R,LAMP_B,0
.db End_PLC,0,0,0
