; A pedestrian crossing (issue #51, docs/plants.md): cars have green until
; a pedestrian presses BUTTON; then yellow for 1 s (Yellow_Timer), then red
; with walk for 6 s (Walk_Timer), then green again. REQUEST holds the press.
.equ BUTTON_R=4
.equ BUTTON_B=Bit0
.equ CAR_RED_R=5
.equ CAR_RED_B=Bit0
.equ CAR_YELLOW_R=5
.equ CAR_YELLOW_B=Bit1
.equ CAR_GREEN_R=5
.equ CAR_GREEN_B=Bit2
.equ WALK_R=5
.equ WALK_B=Bit3
.equ DONT_WALK_R=5
.equ DONT_WALK_B=Bit4
.equ REQUEST_R=6
.equ REQUEST_B=Bit0
.equ YELLOW_OVER_R=6
.equ YELLOW_OVER_B=Bit1
.equ WALKING_R=6
.equ WALKING_B=Bit2
.equ WALK_OVER_R=6
.equ WALK_OVER_B=Bit3
.dseg
PLC_Timer_Top: ; PLC Timers
Yellow_Timer:    .byte 2
Walk_Timer:    .byte 2
.cseg
.db Load_A,BUTTON_R,BUTTON_B,0
.db Or_A,REQUEST_R,REQUEST_B,0
.db And_B,WALK_OVER_R,WALK_OVER_B,0
.db Coil_A,REQUEST_R,REQUEST_B,0
.db Load_A,REQUEST_R,REQUEST_B,0
.db TON,LOW(Yellow_Timer),LOW(1000/Scan),HIGH(1000/Scan)
.db Coil_A,YELLOW_OVER_R,YELLOW_OVER_B,0
.db Load_A,REQUEST_R,REQUEST_B,0
.db And_A,YELLOW_OVER_R,YELLOW_OVER_B,0
.db Coil_A,WALKING_R,WALKING_B,0
.db Load_A,WALKING_R,WALKING_B,0
.db TON,LOW(Walk_Timer),LOW(6000/Scan),HIGH(6000/Scan)
.db Coil_A,WALK_OVER_R,WALK_OVER_B,0
.db Load_A,WALKING_R,WALKING_B,0
.db Coil_A,CAR_RED_R,CAR_RED_B,0
.db Load_A,WALKING_R,WALKING_B,0
.db Coil_A,WALK_R,WALK_B,0
.db Load_B,WALKING_R,WALKING_B,0
.db Coil_A,DONT_WALK_R,DONT_WALK_B,0
.db Load_A,REQUEST_R,REQUEST_B,0
.db And_B,YELLOW_OVER_R,YELLOW_OVER_B,0
.db Coil_A,CAR_YELLOW_R,CAR_YELLOW_B,0
.db Load_B,REQUEST_R,REQUEST_B,0
.db Coil_A,CAR_GREEN_R,CAR_GREEN_B,0
.db End_PLC,0,0,0
