; Two tanks, four fields, two pumps (pump1 fills either tank, pump2 only
; tank2). field1 needs 60 from tank1 (capacity 50), field3 needs 80 from
; tank2 (capacity 40): both must be irrigated while their tank is filled.
; field4 can draw on either tank.
(define (problem tank-p03) (:domain tank)
  (:objects
    tank1 tank2 - tank
    pump1 pump2 - pump
    field1 field2 field3 field4 - field)
  (:init
    (pipe pump1 tank1) (pipe pump1 tank2) (pump-idle pump1) (= (pump-rate pump1) 5) (= (pump-shift pump1) 30)
    (pipe pump2 tank2) (pump-idle pump2) (= (pump-rate pump2) 4) (= (pump-shift pump2) 30)
    (= (level tank1) 20) (= (capacity tank1) 50)
    (= (level tank2) 0) (= (capacity tank2) 40)
    (feeds tank1 field1) (dry field1) (= (flow-rate field1) 6) (= (irrigation-time field1) 10)
    (feeds tank1 field2) (dry field2) (= (flow-rate field2) 4) (= (irrigation-time field2) 5)
    (feeds tank2 field3) (dry field3) (= (flow-rate field3) 8) (= (irrigation-time field3) 10)
    (feeds tank1 field4) (feeds tank2 field4) (dry field4) (= (flow-rate field4) 3) (= (irrigation-time field4) 10))
  (:goal (and (watered field1) (watered field2) (watered field3) (watered field4)))
  (:metric minimize (total-time)))
