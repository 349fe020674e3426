; AVR simplified PLC: the seed's self-holding rungs
.equ INPUT1_R=4
.equ INPUT1_B=Bit0
.equ INPUT2_R=4
.equ INPUT2_B=Bit1
.equ INPUT3_R=4
.equ INPUT3_B=Bit2
.equ COIL1_R=5
.equ COIL1_B=Bit0
.equ COIL2_R=5
.equ COIL2_B=Bit1
.csg
.db   Load_A,INPUT1_R,INPUT1_B,0
.db   And_A,INPUT2_R,INPUT2_B,0
.db   Coil_A,COIL1_R,COIL1_B,0
.db   Load_A,COIL1_R,COIL1_B,0
.db   Or_A,COIL2_R,COIL2_B,0
.db   And_B,INPUT3_R,INPUT3_B,0
.db   Coil_A,COIL2_R,COIL2_B,0
.db   End_PLC,0,0,0
