; A sorter (issue #51, docs/plants.md): the BELT always runs; a TALL part
; is remembered in TALL_COMING until the pusher is out (PUSHER_OUT); PUSH
; goes out when that part is fully in front of the pusher (PART).
.equ PART_R=4
.equ PART_B=Bit0
.equ TALL_R=4
.equ TALL_B=Bit1
.equ PUSHER_OUT_R=4
.equ PUSHER_OUT_B=Bit2
.equ PUSHER_IN_R=4
.equ PUSHER_IN_B=Bit3
.equ BELT_R=5
.equ BELT_B=Bit0
.equ PUSH_R=5
.equ PUSH_B=Bit1
.equ TALL_COMING_R=6
.equ TALL_COMING_B=Bit0
.cseg
.db Load_A,PUSHER_IN_R,PUSHER_IN_B,0
.db Or_B,PUSHER_IN_R,PUSHER_IN_B,0
.db Coil_A,BELT_R,BELT_B,0
.db Load_A,TALL_R,TALL_B,0
.db Or_A,TALL_COMING_R,TALL_COMING_B,0
.db And_B,PUSHER_OUT_R,PUSHER_OUT_B,0
.db Coil_A,TALL_COMING_R,TALL_COMING_B,0
.db Load_A,PART_R,PART_B,0
.db And_A,TALL_COMING_R,TALL_COMING_B,0
.db Or_A,PUSH_R,PUSH_B,0
.db And_B,PUSHER_OUT_R,PUSHER_OUT_B,0
.db Coil_A,PUSH_R,PUSH_B,0
.db End_PLC,0,0,0
