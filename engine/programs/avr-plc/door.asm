; A garage door (issue #51, docs/plants.md): REMOTE opens a closed door
; (BOTTOM) and closes an open one (TOP); the motor (UP, DOWN) stops at the
; limit switches; a blocked EYE while closing opens the door again (REOPEN),
; and a door never closes while it is blocked. OPENING is the remote on a
; closed door (an OR line of this machine holds one contact).
.equ TOP_R=4
.equ TOP_B=Bit0
.equ BOTTOM_R=4
.equ BOTTOM_B=Bit1
.equ EYE_R=4
.equ EYE_B=Bit2
.equ REMOTE_R=4
.equ REMOTE_B=Bit3
.equ UP_R=5
.equ UP_B=Bit0
.equ DOWN_R=5
.equ DOWN_B=Bit1
.equ REOPEN_R=6
.equ REOPEN_B=Bit0
.equ OPENING_R=6
.equ OPENING_B=Bit1
.cseg
.db Load_A,EYE_R,EYE_B,0
.db And_A,DOWN_R,DOWN_B,0
.db Coil_A,REOPEN_R,REOPEN_B,0
.db Load_A,REMOTE_R,REMOTE_B,0
.db And_A,BOTTOM_R,BOTTOM_B,0
.db Coil_A,OPENING_R,OPENING_B,0
.db Load_A,OPENING_R,OPENING_B,0
.db Or_A,REOPEN_R,REOPEN_B,0
.db Or_A,UP_R,UP_B,0
.db And_B,TOP_R,TOP_B,0
.db Coil_A,UP_R,UP_B,0
.db Load_A,REMOTE_R,REMOTE_B,0
.db And_A,TOP_R,TOP_B,0
.db Or_A,DOWN_R,DOWN_B,0
.db And_B,BOTTOM_R,BOTTOM_B,0
.db And_B,EYE_R,EYE_B,0
.db And_B,UP_R,UP_B,0
.db Coil_A,DOWN_R,DOWN_B,0
.db End_PLC,0,0,0
