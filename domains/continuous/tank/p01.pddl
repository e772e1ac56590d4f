; One tank (capacity 50, empty), one pump (5 a unit), one field that needs
; 8 a unit for 10 units: 80 in all, more than the tank holds, so the pump
; must fill the tank while the field is irrigated.
(define (problem tank-p01) (:domain tank)
  (:objects
    tank1 - tank
    pump1 - pump
    field1 - field)
  (:init
    (pipe pump1 tank1) (pump-idle pump1) (= (pump-rate pump1) 5) (= (pump-shift pump1) 30)
    (= (level tank1) 0) (= (capacity tank1) 50)
    (feeds tank1 field1) (dry field1) (= (flow-rate field1) 8) (= (irrigation-time field1) 10))
  (:goal (watered field1))
  (:metric minimize (total-time)))
