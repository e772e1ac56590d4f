; Two tanks, three fields, one pump shared by both tanks. field3 needs
; 10 a unit for 8 units (80), more than tank2 holds (60): tank2 must be
; filled while field3 is irrigated.
(define (problem tank-p02) (:domain tank)
  (:objects
    tank1 tank2 - tank
    pump1 - pump
    field1 field2 field3 - field)
  (:init
    (pipe pump1 tank1) (pipe pump1 tank2) (pump-idle pump1) (= (pump-rate pump1) 6) (= (pump-shift pump1) 30)
    (= (level tank1) 10) (= (capacity tank1) 40)
    (= (level tank2) 0) (= (capacity tank2) 60)
    (feeds tank1 field1) (dry field1) (= (flow-rate field1) 3) (= (irrigation-time field1) 10)
    (feeds tank2 field2) (dry field2) (= (flow-rate field2) 5) (= (irrigation-time field2) 10)
    (feeds tank2 field3) (dry field3) (= (flow-rate field3) 10) (= (irrigation-time field3) 8))
  (:goal (and (watered field1) (watered field2) (watered field3)))
  (:metric minimize (total-time)))
